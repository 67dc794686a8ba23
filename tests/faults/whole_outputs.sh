# Sourced by the fault suites (through fault_lib.sh), soak.sh and soak_python.sh: whether an
# output file was written whole.

# A file ends with a newline (a CSV, JSON or YAML written whole).
ends_whole() {
  [ ! -s "$1" ] || [ "$(tail -c 1 "$1" | od -An -c | tr -d ' ')" = '\n' ]
}
# A PNG ends with its IEND chunk.
png_whole() {
  [ "$(tail -c 8 "$1" | od -An -c | tr -d ' \n')" = 'IEND256B`202' ]
}
# After a run with --out $1: counts each output cut (cut) and each temporary left (left,
# removed then), said through the caller's fault().
check_outputs() {
  for f in "$1"/*.csv "$1"/*.json "$1"/*.yaml; do
    [ ! -e "$f" ] || ends_whole "$f" || { cut=$((cut + 1)); fault "$f cut"; }
  done
  for f in "$1"/*.png "$1"/snapshots/*.png; do
    [ ! -e "$f" ] || png_whole "$f" || { cut=$((cut + 1)); fault "$f cut"; }
  done
  found=$(find "$1" -name '.*.tmp.*' 2>/dev/null)
  if [ -n "$found" ]; then
    left=$((left + $(printf '%s\n' "$found" | wc -l)))
    fault "temporaries left: $found"
    find "$1" -name '.*.tmp.*' -exec rm -f {} +
  fi
}
