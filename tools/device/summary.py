#!/usr/bin/env python3
"""The open GPU targets from `retroaa bench --json` files (tools/device/run.sh writes them).

usage: summary.py BENCH.json ...   Prints one block per file; the issue each line answers in brackets.
"""
import json
import sys


def ratio(a, b):
    return a / b if a is not None and b else float("nan")


def summarise(path):
    with open(path) as f:
        report = json.load(f)
    rows = {row["method"]: row for row in report["rows"]}
    off = rows.get("off")
    samples = max(row["samples"] for row in report["rows"])
    print(f"{path}: {report['renderer_summary']}, {report['width']}x{report['height']}, {samples}x")
    if off is None:
        print("  no `off` row: no ratios")
        return
    target = {4: 1.5, 16: 2.0}.get(samples)
    for name in ("coverage", "reconstruct", "reconstruct@reconstruct_compute=on", "reconstruct@reconstruct_search_radius=1",
                 "resolve+reconstruct"):
        row = rows.get(name)
        if not row:
            continue
        wall = ratio(row["wall_ms"], off["wall_ms"])
        verdict = "" if target is None else (" meets" if wall <= target else " misses") + f" the GPU's <= {target}x"
        own = ", ".join(f"{key[len('plugin.'):]} {ms:.2f}" for key, ms in row["passes_ms"].items()
                        if key.startswith("plugin.") and key != "plugin.lighting")
        print(f"  [19] {name}: wall {wall:.2f}x off{verdict}; GPU {ratio(row['gpu_ms'], off['gpu_ms']):.2f}x; "
              f"ms: after the model pass {row['passes_ms'].get('after_model_pass', 0):.2f}, {own}; "
              f"{row['plugin_bytes_per_pixel']:.0f} B/px")
    resolve = rows.get("resolve")
    if resolve and "reconstruct" in rows:
        share = ratio(rows["reconstruct"]["plugin_bytes_per_pixel"], resolve["plugin_bytes_per_pixel"])
        print(f"  [19] reconstruct holds {share:.1%} of resolve's {resolve['plugin_bytes_per_pixel']:.0f} B/px")
    for name in ("resolve", "resolve@resolve_compute=on"):  # the full-screen resolve, then the compute one
        row = rows.get(name)
        if not row:
            continue
        bound = row.get("passes_traffic_bound_ms", {}).get("plugin.resolve")
        measured = row["passes_ms"].get("plugin.resolve")
        print(f"  [22] {name} pass {measured:.3f} ms, traffic bound {bound:.3f} ms: {ratio(measured, bound):.1f}x "
              f"(target <= 3x) at {report['copy_gb_per_s']:.0f} GB/s")
    for name in ("edge", "edge@resolve_compute=on"):
        edge = rows.get(name)
        if not edge:
            continue
        ideal = edge["evals_per_pixel"] * off["passes_ms"]["lighting"]
        lighting = edge["passes_ms"]["lighting"]
        print(f"  [22] {name} lighting {lighting:.3f} ms against an ideal {ideal:.3f} ms "
              f"({edge['evals_per_pixel']:.3f} evals/px x off's {off['passes_ms']['lighting']:.3f}): "
              f"{ratio(lighting, ideal):.2f}x (target <= 1.5x)")
        print(f"  [22] {name} plugin_overhead_ms {edge['plugin_overhead_ms']:.3f} = "
              f"{ratio(edge['plugin_overhead_ms'], off['gpu_ms']):.0%} of off's {off['gpu_ms']:.3f} ms frame (target <= 25%)")
    print("  wall vs off: " + ", ".join(f"{m} {ratio(r['wall_ms'], off['wall_ms']):.2f}" for m, r in rows.items() if m != "off"))


def main():
    if len(sys.argv) < 2:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    missing = 0
    for path in sys.argv[1:]:
        try:
            summarise(path)
        except FileNotFoundError:
            print(f"{path}: missing (its run failed or ran out of time)")
            missing += 1
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
