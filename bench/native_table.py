"""Google Benchmark JSON (edgelight_bench --benchmark_format=json) -> Markdown tables.

    build/native/bench/edgelight_bench --benchmark_format=json --benchmark_repetitions=3 \
        --benchmark_report_aggregates_only=true > out/native_bench.json
    python3 bench/native_table.py out/native_bench.json
"""
import json
import sys

MESHES = ["cow", "fandisk", "bunny00", "armadillo", "torus_1M"]


def main(path):
    data = json.load(open(path))
    rows = {}
    for b in data["benchmarks"]:
        if b.get("aggregate_name", "median") != "median":
            continue
        name = b["run_name"] if "run_name" in b else b["name"]
        base, _, arg = name.partition("/")
        counter = next((k for k in b if k.startswith("ns_per_")), None)
        if counter is None:
            rows.setdefault(("other", base), {})[arg] = f"{b['real_time']:.3g} {b['time_unit']}"
            continue
        value = b[counter] * 1e9 if b[counter] < 1e-3 else b[counter]  # inverted rates come in seconds
        if not arg.isdigit():
            rows.setdefault(("other", base), {})[arg] = f"{value:.3g} {counter.replace('ns_per_', 'ns/')}"
            continue
        mesh = MESHES[int(arg)] if int(arg) < len(MESHES) else arg
        # Per-call time where the per-item figure rounds to zero (a cache hit).
        cell = f"{value:.2f}" if value >= 0.01 else f"≈0 ({b['real_time']:.3g} {b['time_unit']}/call)"
        rows.setdefault((counter, base), {})[mesh] = cell
    ctx = data["context"]
    print(f"Machine: {ctx.get('num_cpus')} CPUs at {ctx.get('mhz_per_cpu')} MHz, load {ctx.get('load_avg')}; "
          f"median of {ctx.get('repetitions', 3)} repetitions.\n")
    print("| kernel | unit | " + " | ".join(MESHES) + " |")
    print("|---|---|" + "---|" * len(MESHES))
    for (counter, base), cells in sorted(rows.items()):
        if counter == "other":
            continue
        unit = counter.replace("ns_per_", "ns/")
        print(f"| {base.replace('BM_', '')} | {unit} | " + " | ".join(cells.get(m, "") for m in MESHES) + " |")
    others = [(b, c) for (k, b), c in rows.items() if k == "other"]
    if others:
        print("\n| benchmark | time |\n|---|---|")
        for base, cells in sorted(others):
            for arg, t in sorted(cells.items()):
                print(f"| {base.replace('BM_', '')}{'/' + arg if arg else ''} | {t} |")


if __name__ == "__main__":
    main(sys.argv[1])
