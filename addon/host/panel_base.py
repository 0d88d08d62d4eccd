"""The base of EdgeLight's panels in the Properties editor: shown only while EdgeLight renders."""


class EdgeLightPanel:
    bl_space_type = 'PROPERTIES'
    bl_region_type = 'WINDOW'
    COMPAT_ENGINES = {'EDGELIGHT'}

    @classmethod
    def poll(cls, context):
        return context.engine in cls.COMPAT_ENGINES


class EdgeLightMaterialPanel(EdgeLightPanel):
    """A panel of the Material tab: shown while EdgeLight renders and a material is there."""
    bl_context = "material"

    @classmethod
    def poll(cls, context):
        return super().poll(context) and context.material is not None
