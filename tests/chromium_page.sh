# Sourced by replay_chromium.sh and room_replay_chromium.sh: a replay page in headless
# Chromium. Sets $chromium (or skips, exit 77, when it is not installed, unless
# MAZE_MAPPER_REQUIRE_CHROMIUM is set: then fails) and $dir (a temporary folder, removed on
# exit), and defines
#   fail MESSAGE        prints it and the heads of chromium.err and dom.html, exits 1;
#   browser ARGS...     headless Chromium with a profile of its own, at most 60 s;
#   self_contained PAGE fails when the page refers to anything outside itself;
#   load_page URL WHAT [WIDTHxHEIGHT]
#                       the DOM after the page's script into $dir/dom.html (in a window of
#                       that size, else Chromium's own); fails on a JavaScript error
#                       (data-js-error on <body>), a script that did not finish
#                       (data-replay-ready) or no step slider with frames;
#   fits_window SIZE [NAME [HASH]]
#                       loads the page $page in a window of SIZE (WIDTHxHEIGHT) and fails when
#                       its status line or key help is cut (data-cut on <body>); then a
#                       screenshot of it (at $page#HASH), $dir/shot-SIZE.png, which must not be blank
#                       ($png_spread), copied into $SCREENSHOT_DIR as NAME-SIZE.png when that is set.
chromium=$(command -v chromium || command -v chromium-browser || true)
if [ -z "$chromium" ]; then
  if [ -n "${MAZE_MAPPER_REQUIRE_CHROMIUM:-}" ]; then
    echo "FAIL: chromium is not installed and MAZE_MAPPER_REQUIRE_CHROMIUM is set (scripts/install-test-deps.sh)" >&2
    exit 1
  fi
  echo "SKIP: chromium is not installed (scripts/install-test-deps.sh installs it)"
  exit 77
fi

dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() {
  echo "FAIL: $1" >&2
  for f in "$dir/chromium.err" "$dir/dom.html"; do
    [ -f "$f" ] && { echo "--- $f (head) ---" >&2; head -c 3000 "$f" >&2; echo >&2; }
  done
  exit 1
}

browser() {
  timeout 60 "$chromium" --headless --no-sandbox --disable-gpu --no-first-run --disable-extensions \
    --disable-dev-shm-usage --user-data-dir="$dir/profile" --virtual-time-budget=10000 "$@" 2>> "$dir/chromium.err"
}

self_contained() {
  [ -s "$1" ] || fail "no replay.html"
  if grep -Eq '(src|href)=|https?:|@import|fetch\(' "$1"; then fail "replay.html refers to something outside itself"; fi
}

load_page() {
  size=${3:-}
  if [ -n "$size" ]; then
    browser --window-size="$(echo "$size" | tr x ,)" --dump-dom "$1" > "$dir/dom.html" || fail "chromium --dump-dom $2 failed"
  else
    browser --dump-dom "$1" > "$dir/dom.html" || fail "chromium --dump-dom $2 failed"
  fi
  grep -q 'data-js-error' "$dir/dom.html" && fail "a JavaScript error $2: $(grep -o 'data-js-error="[^"]*"' "$dir/dom.html")"
  grep -q 'data-replay-ready="[1-9]' "$dir/dom.html" || fail "the page's script did not finish $2 (no data-replay-ready)"
  grep -q '<input type="range" id="step" min="0" max="[1-9][0-9]*"' "$dir/dom.html" || fail "no step slider with frames $2"
}

fits_window() {
  load_page "file://$page" "in a $1 window" "$1"
  cut=$(grep -o '<body[^>]*>' "$dir/dom.html" | sed -n 's/.*data-cut="\([^"]*\)".*/\1/p')
  case ",$cut," in
    *,status,*|*,keys,*|*,controls,*) fail "in a $1 window the header is cut: $cut" ;;
  esac
  browser --window-size="$(echo "$1" | tr x ,)" --hide-scrollbars --screenshot="$dir/shot-$1.png" "file://$page${3:+#$3}" > /dev/null ||
    fail "chromium --screenshot at $1 failed"
  "$png_spread" "$dir/shot-$1.png" || fail "blank screenshot at $1"
  if [ -n "${SCREENSHOT_DIR:-}" ]; then cp "$dir/shot-$1.png" "$SCREENSHOT_DIR/${2:-replay}-$1.png"; fi
}
