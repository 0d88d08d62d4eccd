"""The base of EdgeLight's panels in the Properties editor: shown only while EdgeLight renders."""


class EdgeLightPanel:
    bl_space_type = 'PROPERTIES'
    bl_region_type = 'WINDOW'
    COMPAT_ENGINES = {'EDGELIGHT'}

    @classmethod
    def poll(cls, context):
        return context.engine in cls.COMPAT_ENGINES
