#!/usr/bin/env python3
"""Judges the options dialog as the player sees it, from --aa-options' capture: options.png (the window
with the dialog), screen.png (the video options behind it) and the layout in capture.jsonl (the dialog's
box, every text it draws with its box and the size it takes in its font, and every anti-aliasing choice's
label and hint with the widths they take and have).

usage: options_check.py OPTIONS_DIR
  - the panel is drawn: inside the dialog's box at least 90% of the pixels differ from the screen behind
    (a dialog without its panel leaves them as they were, text aside)
  - every text takes one line that fits its box, and no two texts overlap
  - every choice's label fits the spinner and its hint fits its line
Prints one line per check, then 'N passed, N failed'; exit 1 when any failed."""
import json
import pathlib
import re
import subprocess
import sys

folder = pathlib.Path(sys.argv[1])
record = json.loads((folder / "capture.jsonl").read_text().splitlines()[0])
results = []


def check(name, ok, detail):
    results.append(ok)
    print(("ok    " if ok else "FAIL  ") + name + ": " + detail)


def cut(box):
    x, y, w, h = box
    return f"{w}x{h}+{x}+{y}"


# The panel: pixels changed by more than 2/255 from the screen behind, inside the dialog's box.
diff = subprocess.run(["oiiotool", "--fail", str(2 / 255), str(folder / record["screen"]), "--cut", cut(record["panel"]),
                       str(folder / record["image"]), "--cut", cut(record["panel"]), "--diff"],
                      capture_output=True, text=True).stdout
changed = [float(m) for m in re.findall(r"pixels \(([0-9.]+)%\) over 0\.0078", diff)]
check("the dialog's panel is drawn over the screen behind", bool(changed) and changed[0] >= 90,
      f"{changed[0] if changed else 'no figure'}% of the pixels in the dialog's box changed")

texts = record["texts"]
for text in texts:
    box_w, width, lines = text["box"][2], text["size"][0], text["lines"]
    check(f"'{text['text']}' fits its box on one line", lines == 1 and width <= box_w,
          f"{width} px wide in {box_w}, {lines} lines")


def drawn(text):
    """The band the text is drawn in: its box's columns, its height centred on the box's middle."""
    x, y, w, h = text["box"]
    middle, half = y + h / 2, text["size"][1] / 2
    return x, x + w, middle - half, middle + half


def overlap(a, b):
    p, q = drawn(a), drawn(b)
    return p[0] < q[1] and q[0] < p[1] and p[2] < q[3] and q[2] < p[3]


overlaps = [(a["text"], b["text"]) for i, a in enumerate(texts) for b in texts[i + 1:] if overlap(a, b)]
check("no two texts overlap", not overlaps, "; ".join(f"'{a}' over '{b}'" for a, b in overlaps) or "none")

for choice in record["choices"]:
    check(f"choice '{choice['label']}' fits the spinner", choice["label_width"] <= record["label_box"][2],
          f"{choice['label_width']} px in {record['label_box'][2]}")
    check(f"its hint fits one line", choice["hint_width"] <= record["hint_box"][2],
          f"'{choice['hint']}': {choice['hint_width']} px in {record['hint_box'][2]}")

failed = results.count(False)
print(f"{len(results) - failed} passed, {failed} failed")
sys.exit(1 if failed else 0)
