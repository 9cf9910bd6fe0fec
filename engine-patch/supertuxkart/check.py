#!/usr/bin/env python3
"""The SuperTuxKart check's assertions, on `retroaa score`'s report.json and the capture log.

usage: check.py CAPTURE_DIR PATCH_DIR [--edges] [--sky] [--whole-frame] [--race] [--forward]
  --edges  every multi-sample method, and temporal converged on the still frame, beats off's edge PSNR;
           edge within 0.5 dB of per-sample's at <= 1.5 evaluations per pixel (a track whose
           silhouettes stand against geometry)
  --sky    every method but the full-screen filters leaves the sky as off has it (a track with sky)
  --whole-frame  the MSAA G-buffer methods win inside STK's whole frame (its combine and sky composed per
           slice): per-sample >= off + 3 dB edge PSNR and >= reconstruct's; every slice method above
           off; edge within 0.5 dB of per-sample at <= 1.5 evaluations per pixel; reconstruct within
           0.5 dB of off's interior PSNR
  --race   a driven race (race.sh): every method scored over the same frames; temporal's edge PSNR at
           least fxaa's, its flicker at most fxaa's, its interior PSNR at least off's - 1 dB, its kart (the
           score's "kart" region) at least off's, and its whole-frame PSNR swinging at most 0.5 dB from frame
           to frame
  --forward  every method's interior PSNR at least off's - 1 dB: nothing STK's forward passes drew
           (transparents, the karts' exhaust smoke) is lost (a capture with its effects on)
Exit 1 naming every failed assertion; prints 'N passed, N failed'."""
import json
import pathlib
import sys

captures, patches = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
edges, sky, whole_frame, race, forward = ("--" + flag in sys.argv[3:]
                                         for flag in ("edges", "sky", "whole-frame", "race", "forward"))
rows = {row["spec"]: row for row in json.loads((captures / "report.json").read_text())}
log = [json.loads(line) for line in (captures / "capture.jsonl").read_text().splitlines() if line.strip()]
results = []


def check(name, ok, detail):
    results.append(ok)
    print(("ok    " if ok else "FAIL  ") + name + ": " + detail)


for record in log:
    check(f"{record['spec']} raised no GL error", record.get("gl_errors", -1) == 0,
          f"{record.get('gl_errors')} GL errors while it rendered")
    check(f"{record['spec']} ran without a retroaa warning", record.get("retroaa", {}).get("warnings", 0) == 0,
          f"{record.get('retroaa', {}).get('warnings')} warnings")
off = rows["off"]
base = {spec: spec.split("@")[0].split("/")[0].split("+")[0] for spec in rows}
multi = [spec for spec in rows if base[spec] in
         ("resolve", "edge", "adaptive", "aggregate", "per-sample", "smaa-s2x", "coverage", "reconstruct")]
# temporal: STK jitters its projection by the plugin's offset, and the capture waits out the history.
for spec in multi + [spec for spec in rows if base[spec] == "temporal"] if edges else []:
    check(f"{spec} beats off's edge PSNR", rows[spec]["edge_psnr_db"] > off["edge_psnr_db"],
          f"{rows[spec]['edge_psnr_db']:.2f} dB against {off['edge_psnr_db']:.2f} dB")
# The MSAA G-buffer methods beat off inside the whole frame: the slice methods compose each sample, `resolve`
# composes once on the resolved surface (its 2-of-4 splits follow their neighbours: docs/methods/resolve.md).
gbuffer = [spec for spec in rows if base[spec] in ("resolve", "edge", "adaptive", "aggregate", "per-sample", "smaa-s2x")]
for spec in gbuffer if whole_frame and not edges else []:  # --edges checks them already
    check(f"{spec} beats off's edge PSNR", rows[spec]["edge_psnr_db"] > off["edge_psnr_db"],
          f"{rows[spec]['edge_psnr_db']:.2f} dB against {off['edge_psnr_db']:.2f} dB")
if whole_frame and "per-sample" in rows:
    per_sample = rows["per-sample"]
    check("per-sample gains at least 3 dB edge PSNR over off", per_sample["edge_psnr_db"] >= off["edge_psnr_db"] + 3,
          f"{per_sample['edge_psnr_db']:.2f} dB against {off['edge_psnr_db']:.2f} dB")
    if "reconstruct" in rows:
        check("per-sample's edge PSNR at least reconstruct's",
              per_sample["edge_psnr_db"] >= rows["reconstruct"]["edge_psnr_db"],
              f"{per_sample['edge_psnr_db']:.2f} dB against {rows['reconstruct']['edge_psnr_db']:.2f} dB")
if whole_frame and "reconstruct" in rows:
    reconstruct = rows["reconstruct"]
    check("reconstruct within 0.5 dB of off's interior PSNR",
          reconstruct["interior_psnr_db"] >= off["interior_psnr_db"] - 0.5,
          f"{reconstruct['interior_psnr_db']:.2f} dB against {off['interior_psnr_db']:.2f} dB")
if (edges or whole_frame) and "edge" in rows and "per-sample" in rows:
    edge, per_sample = rows["edge"], rows["per-sample"]
    check("edge within 0.5 dB of per-sample's edge PSNR", edge["edge_psnr_db"] >= per_sample["edge_psnr_db"] - 0.5,
          f"{edge['edge_psnr_db']:.2f} dB against {per_sample['edge_psnr_db']:.2f} dB")
    check("edge lights at most 1.5 evaluations per pixel", edge["evaluations_per_pixel"] <= 1.5,
          f"{edge['evaluations_per_pixel']:.3f}")
if race:
    frames = {spec: row["frames"] for spec, row in rows.items()}
    check("every method scored over the same frames", len(set(frames.values())) == 1 and min(frames.values()) > 1,
          ", ".join(f"{spec} {n}" for spec, n in frames.items()))
    if "temporal" in rows and "fxaa" in rows:
        check("temporal's edge PSNR at least fxaa's in the race",
              rows["temporal"]["edge_psnr_db"] >= rows["fxaa"]["edge_psnr_db"],
              f"{rows['temporal']['edge_psnr_db']:.2f} dB against {rows['fxaa']['edge_psnr_db']:.2f} dB")
        check("temporal flickers at most as much as fxaa in the race",
              rows["temporal"]["flicker"] <= rows["fxaa"]["flicker"],
              f"{rows['temporal']['flicker']:.4f} against {rows['fxaa']['flicker']:.4f}")
    if "temporal" in rows:
        temporal = rows["temporal"]
        check("temporal's interior PSNR at least off's - 1 dB in the race",
              temporal["interior_psnr_db"] >= off["interior_psnr_db"] - 1,
              f"{temporal['interior_psnr_db']:.2f} dB against {off['interior_psnr_db']:.2f} dB")
        kart, off_kart = temporal["regions"]["kart"]["psnr_db"], off["regions"]["kart"]["psnr_db"]
        check("temporal's kart PSNR at least off's in the race", kart >= off_kart,
              f"{kart:.2f} dB against {off_kart:.2f} dB")
        check("temporal's PSNR swings at most 0.5 dB from frame to frame in the race",
              temporal["psnr_swing_db"] <= 0.5, f"{temporal['psnr_swing_db']:.2f} dB (off {off['psnr_swing_db']:.2f})")
for spec, row in rows.items() if forward else []:
    check(f"{spec} keeps what the forward passes drew (interior PSNR at least off's - 1 dB)",
          row["interior_psnr_db"] >= off["interior_psnr_db"] - 1,
          f"{row['interior_psnr_db']:.2f} dB against {off['interior_psnr_db']:.2f} dB")
# FXAA, SMAA and temporal accumulation filter every pixel of the display, sky included: they are not
# held to it.
for spec, row in rows.items() if sky else []:
    if base[spec] in ("fxaa", "smaa", "temporal") or spec == "stk-mlaa":
        continue
    check(f"{spec} leaves the sky as off has it", row["sky_pixels"] > 0 and row["sky_kept"] is not None
          and row["sky_kept"] >= 0.999, f"{row['sky_kept']} of {row['sky_pixels']} sky pixels within 1/255 of off's")
touched = [line[6:].strip() for p in sorted(patches.glob("*.patch")) for line in p.read_text().splitlines()
           if line.startswith("+++ b/")]
shaders = [path for path in touched if path.startswith("data/") or path.endswith((".frag", ".vert", ".glsl", ".comp"))]
check("the patches touch no STK shader and nothing under data/", not shaders and bool(touched),
      ", ".join(shaders) if shaders else f"{len(touched)} files, none a shader")
print(f"{sum(results)} passed, {len(results) - sum(results)} failed")
sys.exit(0 if all(results) else 1)
