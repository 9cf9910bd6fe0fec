#!/usr/bin/env python3
"""The cost targets of docs/results.md#what-the-passes-cost, on cost.sh's reports: per track, whether
edge's own passes (every plugin pass but the host's lighting) are at most 0.3x off's wall and no more than
per-sample's, edge's wall at most 3x off's (edge as a player runs it, without the floors' replays; resolve's
beside it), every measured pass within 3x its floor, and aggregate below edge's evaluations at edge's edge
PSNR (within 0.1 dB). A benchmark on a noisy machine: it prints each
target met or missed with the figures, and exits 0 either way (tests assert only counters).

usage: cost_targets.py OUT TRACK..."""
import json
import pathlib
import sys

out = pathlib.Path(sys.argv[1])
missed = met = 0


def target(name, ok, detail):
    global missed, met
    met += ok
    missed += not ok
    print(f"| {name} | {'met' if ok else 'missed'} | {detail} |")


print("| target | | figures |\n|---|---|---|")
for track in sys.argv[2:]:
    rows = {row["spec"]: row for row in json.loads((out / track / "report.json").read_text())}
    off, resolve, edge_as_played = rows["off"], rows["resolve"], rows["edge"]
    edge, per_sample, aggregate = (rows[m + "@measure_pass_floors=on"] for m in ("edge", "per-sample", "aggregate"))
    target(f"{track}: edge's own passes <= 0.3x off's wall", edge["own_passes_vs_off_wall"] <= 0.3,
           f"{edge['own_passes_ms']:.1f} ms, {edge['own_passes_vs_off_wall']:.2f}x off's {off['wall_ms']:.1f} ms")
    target(f"{track}: edge's own passes <= per-sample's", edge["own_passes_ms"] <= per_sample["own_passes_ms"],
           f"{edge['own_passes_ms']:.1f} against {per_sample['own_passes_ms']:.1f} ms")
    target(f"{track}: edge's wall <= 3x off's", edge_as_played["wall_vs_off"] <= 3.0,
           f"{edge_as_played['wall_vs_off']:.2f}x (resolve's {resolve['wall_vs_off']:.2f}x: the host's multisampled "
           f"geometry and one pass of ours, {resolve['own_passes_ms']:.1f} ms; with the floors' replays "
           f"{edge['wall_vs_off']:.2f}x)")
    for spec, row in (("edge", edge), ("per-sample", per_sample), ("aggregate", aggregate)):
        passes = row["passes_ms"]
        ratios = {name: ms / passes[name + ".floor"] for name, ms in passes.items()
                  if not name.endswith(".floor") and passes.get(name + ".floor", 0) > 0}
        worst = max(ratios, key=ratios.get)
        own_floor = sum(passes[name + ".floor"] for name in ratios)
        target(f"{track}: every {spec} pass <= 3x its floor", ratios[worst] <= 3.0,
               f"worst {worst} {ratios[worst]:.2f}x; its passes' floors sum to {own_floor:.1f} ms "
               f"({own_floor / off['wall_ms']:.2f}x off's wall)")
    target(f"{track}: aggregate fewer evaluations than edge at its edge PSNR",
           aggregate["evaluations_per_pixel"] < edge["evaluations_per_pixel"]
           and aggregate["edge_psnr_db"] >= edge["edge_psnr_db"] - 0.1,
           f"aggregate {aggregate['evaluations_per_pixel']:.2f} evals/px at {aggregate['edge_psnr_db']:.2f} dB, "
           f"edge {edge['evaluations_per_pixel']:.2f} at {edge['edge_psnr_db']:.2f} dB")
print(f"\n{met} met, {missed} missed")
