// A Flamenco custom job type: renders a .blend's frames with the EdgeLight engine, chunk_size
// frames per task, through Flamenco's "blender-render" command. Put this file in the Manager's
// scripts/ directory (docs/farm.md, which also says what of this is untested).
const JOB_TYPE = {
    label: "EdgeLight Render",
    description: "Render frames with the EdgeLight engine (needs the add-on on every Worker)",
    settings: [
        { key: "frames", type: "string", required: true,
          eval: "f'{C.scene.frame_start}-{C.scene.frame_end}'",
          description: "Frames to render, e.g. '1-24' or '1, 5-9'" },
        { key: "chunk_size", type: "int32", default: 4,
          description: "Frames per task (one Blender process each)" },
        { key: "render_output_path", type: "string", subtype: "file_path", editable: false,
          eval: "f'{jobname}/render/######'",
          description: "Blender's output path: the '#'s become the frame number" },
        { key: "legacy_addon", type: "bool", default: false,
          description: "Workers run Blender 3.x with EdgeLight as a legacy add-on (--addons edgelight); off for 4.2+, where the extension is enabled in the Worker's preferences" },
        { key: "blendfile", type: "string", required: true, visible: "web",
          description: "The .blend to render" },
        { key: "format", type: "string", required: true, visible: "web",
          eval: "C.scene.render.image_settings.file_format" },
    ]
};

// -E alone only warns when the engine is missing, and the scene's own engine would render:
// fail the task instead.
const ENGINE_CHECK = "import bpy; assert bpy.context.scene.render.engine == 'EDGELIGHT', 'EdgeLight is not enabled'";

function compileJob(job) {
    const settings = job.settings;
    if (!settings.render_output_path) {
        throw "no render_output_path setting";
    }
    const argsBefore = ["--python-exit-code", "1"];
    if (settings.legacy_addon) {
        argsBefore.push("--addons", "edgelight");
    }
    for (const chunk of frameChunker(settings.frames, settings.chunk_size)) {
        const task = author.Task(`render-${chunk}`, "blender");
        task.addCommand(author.Command("blender-render", {
            exe: "{blender}",
            exeArgs: "{blenderArgs}",
            argsBefore: argsBefore,
            blendfile: settings.blendfile,
            args: [
                "-E", "EDGELIGHT",
                "--python-expr", ENGINE_CHECK,
                "--render-output", settings.render_output_path,
                "--render-format", settings.format,
                // Flamenco's chunks are "1-4" or "1,3"; Blender's ranges are "1..4".
                "--render-frame", chunk.replace(/-/g, ".."),
            ],
        }));
        job.addTask(task);
    }
}
