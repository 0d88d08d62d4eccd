// Checks a Flamenco job type without Flamenco: acorn parses it as ES2015 (Flamenco runs job
// types in goja, an ES5.1 engine with most of ES2015), it declares JOB_TYPE and compileJob, and
// compileJob, run against stand-ins for Flamenco's author / frameChunker, makes one
// blender-render command per chunk. Prints them as JSON for farm_test.py to run with Blender.
//   node flamenco_check.js ACORN_DIR JOB_TYPE.js BLENDFILE OUTPUT FRAMES CHUNK LEGACY(0|1)
const fs = require("fs");
const vm = require("vm");
const [acornDir, file, blendfile, output, frames, chunkSize, legacy] = process.argv.slice(2);
const acorn = require(require("path").resolve(acornDir));

const source = fs.readFileSync(file, "utf8");
const ast = acorn.parse(source, { ecmaVersion: 2015, sourceType: "script" });
const names = ast.body.flatMap((n) =>
    n.type === "FunctionDeclaration" ? [n.id.name]
        : n.type === "VariableDeclaration" ? n.declarations.map((d) => d.id.name) : []);
for (const want of ["JOB_TYPE", "compileJob"]) {
    if (!names.includes(want)) throw new Error(`${file} declares no ${want}`);
}

// The stand-in chunker: frames as "1-6" or "1,3,5-9", chunks of consecutive frames as "a-b".
function frameChunker(spec, size) {
    const all = [];
    for (const part of String(spec).split(",")) {
        const [a, b] = part.trim().split("-").map(Number);
        for (let f = a; f <= (isNaN(b) ? a : b); f++) all.push(f);
    }
    const chunks = [];
    for (let i = 0; i < all.length; i += size) {
        const c = all.slice(i, i + size);
        chunks.push(c.length > 1 ? `${c[0]}-${c[c.length - 1]}` : `${c[0]}`);
    }
    return chunks;
}

const tasks = [];
const sandbox = {
    frameChunker,
    print: () => {},
    author: {
        Task: (name, type) => { const t = { name, type, commands: [], addCommand(c) { this.commands.push(c); } }; return t; },
        Command: (type, params) => ({ type, params }),
    },
};
vm.createContext(sandbox);
vm.runInContext(source, sandbox, { filename: file });
const settingKeys = vm.runInContext("JOB_TYPE.settings.map((s) => s.key)", sandbox);  // const: not a sandbox property
const job = {
    settings: { frames, chunk_size: Number(chunkSize), render_output_path: output, blendfile,
                format: "PNG", legacy_addon: legacy === "1" },
    addTask: (t) => tasks.push(t),
};
for (const key of Object.keys(job.settings)) {
    if (!settingKeys.includes(key)) throw new Error(`JOB_TYPE has no setting ${key}`);
}
vm.runInContext("compileJob", sandbox)(job);
console.log(JSON.stringify(tasks.map((t) => ({ name: t.name, type: t.type, commands: t.commands }))));
