#!/usr/bin/env bash
# The anti-aliasing choice in SuperTuxKart's graphics settings, as a player makes it: from the menu, the
# video options' custom settings dialog shows CHOICE and is applied (OUT/options/options.png, the window
# with the dialog, judged by options_check.py), its hint the expected cost; a race started afterwards
# renders with the choice saved in config.xml and keeps what it cost there, which the dialog then shows
# (OUT/measured/options.png); a saved choice this build does not know falls back to off, with one message
# naming it.
#   usage: options.sh STK_BINARY CHOICE OUT
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
binary=$1 choice=$2 out=$3
data=/usr/share/games/supertuxkart
rm -rf "$out"
mkdir -p "$out/options" "$out/home"
out=$(cd "$out" && pwd)
export RETROAA_STK_HOME=$out/home HOME=$out/home XDG_CONFIG_HOME=$out/home/config XDG_DATA_HOME=$out/home/data
export XDG_CACHE_HOME=$out/home/cache SUPERTUXKART_DATADIR=$data LP_NUM_THREADS=${LP_NUM_THREADS:-2}
export MESA_SHADER_CACHE_DIR=${RETROAA_STK_SHADER_CACHE:-/var/cache/retroaa/mesa-shader-cache}
config=$out/home/config/supertuxkart/config-0.10/config.xml
failed=0 checks=0
check() {  # NAME OK DETAIL
  checks=$((checks + 1))
  if [ "$2" = 1 ]; then echo "ok    $1: $3"; else echo "FAIL  $1: $3"; failed=$((failed + 1)); fi
}
dialog() {  # DIR CHOICE: STK from its menu into the dialog showing CHOICE, written to DIR, then Apply
  mkdir -p "$1"
  # The dialog wants a menu at least 768 high to lay its rows out (STK's own warns below that).
  xvfb-run -a -s "-screen 0 1024x768x24" timeout --kill-after=15 300 "$binary" --screensize=1024x768 --windowed \
    --no-sound --enable-dynamic-lights --aa-capture="$1" --aa-options="$2" >"$1/stk.log" 2>&1 ||
    { tail -20 "$1/stk.log" >&2; echo "options: SuperTuxKart failed in the options dialog ($1/stk.log)" >&2; exit 1; }
}
judge() {  # DIR: the picture as the window shows it, judged: the panel drawn, every text on one line
  # inside its box, none over another, every choice's label and hint fitting.
  python3 "$here/options_check.py" "$1" | sed 's/^\([0-9]* passed\)/dialog: \1/' | tee "$1/check.txt"
  check "the dialog as drawn" "$(grep -q '^dialog: [0-9]* passed, 0 failed' "$1/check.txt" && echo 1)" \
    "$1/options.png; $(tail -1 "$1/check.txt")"
}
shown() {  # DIR: every text the dialog drew, on one line
  python3 -c 'import json,sys; r=json.loads(open(sys.argv[1]).readline()); print(" | ".join(t["text"] for t in r["texts"]))' \
    "$1/capture.jsonl"
}
hint_says() {  # DIR PHRASE NAME: one of the dialog's texts (the shown choice's hint) holds PHRASE
  local texts
  texts=$(shown "$1")
  check "$3" "$(case "$texts" in *"$2"*) echo 1;; esac)" \
    "$(grep -o "[^|]*$2[^|]*" <<<"$texts" || echo "no text holds '$2'")"
}
captured_spec() {  # DIR: the method a capture rendered
  python3 -c 'import json,sys; print(json.loads(open(sys.argv[1]).readline())["spec"])' "$1/capture.jsonl"
}
dialog "$out/options" "$choice"
saved=$(sed -n 's/.*<retroaa value="\([^"]*\)".*/\1/p; s/^ *retroaa="\([^"]*\)".*/\1/p' "$config" | head -1)
check "the dialog's Apply saved the choice in config.xml" "$([ "$saved" = "$choice" ] && echo 1)" "retroaa=\"$saved\""
judge "$out/options"
hint_says "$out/options" "Expected: " "before it has run, the choice's hint gives its expected cost"

# A race from the saved choice (the capture's method "chosen" is whatever is in effect), long enough for
# its cost to be read (every 30 frames, never waited for).
bash "$here/capture.sh" "$binary" olivermath 320x240 40 chosen "$out/race" 1 >/dev/null
spec=$(captured_spec "$out/race")
check "a race renders with the saved choice" "$([ "$spec" = "$choice" ] && echo 1)" "captured '$spec'"
# What the race measured is kept in config.xml: the dialog, opened after a restart, shows it.
measured=$(sed -n 's/^ *retroaa_measured="\([^"]*\)".*/\1/p' "$config" | head -1)
check "the race's measured cost is kept in config.xml" "$(case ";$measured" in *";$choice "*) echo 1;; esac)" \
  "retroaa_measured=\"$measured\""
dialog "$out/measured" "$choice"
judge "$out/measured"
hint_says "$out/measured" "Measured here: " "after it has run, the choice's hint gives its measured cost"

# An old or foreign config.xml: a choice this build does not know.
sed -i 's/retroaa="[^"]*"/retroaa="no-such-method"/' "$config"
bash "$here/capture.sh" "$binary" olivermath 320x240 20 chosen "$out/unknown" 1 >/dev/null
spec=$(captured_spec "$out/unknown")
messages=$(grep -c "saved anti-aliasing 'no-such-method'" "$out/home/config/supertuxkart/config-0.10/stdout.log" || true)
check "an unknown saved choice falls back to off" "$([ "$spec" = off ] && echo 1)" "captured '$spec'"
check "with one message naming it" "$([ "$messages" = 1 ] && echo 1)" "$messages messages"
# A choice made in config.xml that the dialog's list does not name (a preset): shown as "Custom" and
# kept by Apply.
sed -i 's/retroaa="[^"]*"/retroaa="preset=high"/' "$config"
dialog "$out/custom" preset=high
check "a config.xml choice outside the list shows as Custom" "$(case " | $(shown "$out/custom") | " in *" | Custom | "*) echo 1;; esac)" \
  "$(grep -o 'retroaa="[^"]*"' "$config")"
check "and Apply keeps it" "$(grep -q 'retroaa="preset=high"' "$config" && echo 1)" "$(grep -o 'retroaa="[^"]*"' "$config")"
echo "$((checks - failed)) passed, $failed failed"
[ "$failed" = 0 ]
