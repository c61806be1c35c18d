#!/bin/bash
# A design report's first screen as a real browser draws it: headless Chromium (Debian's
# `chromium`, not a dependency of isolab: apt-get install chromium) opens DIR/design.html and
# writes a PNG of the window.
#
#   scripts/screenshot_report.sh DIR [OUT.png] [WIDTHxHEIGHT]
#
# OUT defaults to ./design_html_screen.png (outside DIR, whose files are the design's), the window
# to 1280x900. Exit 2 without chromium or without DIR/design.html.
set -euo pipefail
dir=${1:?usage: scripts/screenshot_report.sh DIR [OUT.png] [WIDTHxHEIGHT]}
out=${2:-design_html_screen.png}
size=${3:-1280x900}
page="$(realpath "$dir")/design.html"
[[ -f $page ]] || { echo "screenshot_report.sh: $page does not exist" >&2; exit 2; }
browser=$(command -v chromium || command -v chromium-browser || true)
[[ -n $browser ]] || { echo "screenshot_report.sh: chromium is not installed" >&2; exit 2; }
profile=$(mktemp -d)
trap 'rm -rf "$profile"' EXIT
"$browser" --headless --no-sandbox --disable-gpu --hide-scrollbars --user-data-dir="$profile" \
  --window-size="${size/x/,}" --screenshot="$(realpath -m "$out")" "file://$page" 2>/dev/null
echo "$out"
