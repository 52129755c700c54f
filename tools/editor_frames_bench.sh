#!/usr/bin/env bash
# Frame times of the editor on FIREHYDRANT with the paper's pose (issue 24, docs/editor.md "Frame timings"):
# orbiting, dragging the whole cage with G, and both with three panes, driven by xdotool under Xvfb (llvmpipe),
# read from --log-frames. Prints one row per scenario: frames per second over the motion, and the mean of each
# stage of the frames drawn during it.
#   tools/editor_frames_bench.sh BUILD_DIR [MODELS_DIR] [SECONDS]
set -euo pipefail
build=${1:?usage: editor_frames_bench.sh BUILD_DIR [MODELS_DIR] [SECONDS]}
models=${2:-$(cd "$(dirname "$0")/../.." && pwd)/shared/models}
seconds=${3:-6}
exe=$(cd "$build" && pwd)/app/somicage
fh=$models/firehydrant
[ -f "$fh/fireHydrant.obj" ] || { echo "FIREHYDRANT not found in $models" >&2; exit 1; }
work=$(mktemp -d)
[ -n "${KEEP:-}" ] && echo "work: $work" >&2 || trap 'rm -rf "$work"' EXIT

cat > "$work/run.sh" <<'SH'
set -u
scenario=$1; shift
log=$WORK/$scenario.log
mkdir -p "$WORK/config"  # a private autosave and recent list: a leftover autosave's question would eat the keys
XDG_CONFIG_HOME=$WORK/config "$EXE" --size 1000x700 --log-actions --log-frames "$FH/fireHydrant.obj" "$FH/fireHydrant_cages_triangulated.obj" \
  "$FH/fireHydrant_cages_triangulated_deformed.obj" "$@" > "$log" 2>&1 & pid=$!
timeout 60 xdotool search --sync --onlyvisible --name 'SomiCage' > /dev/null || { echo "no window"; exit 3; }
for i in $(seq 1 1200); do grep -q '^job precompute' "$log" && break; sleep 0.1; done
xdotool mousemove 700 400; sleep 3  # the measurement settles, the first deformation is done
case $scenario in
  orbit*) xdotool keydown alt mousedown 1 ;;
  drag*) xdotool key a; sleep 1; xdotool key g ;;
esac
sleep 0.5
start_lines=$(grep -c '^frame ' "$log"); t0=$(date +%s.%N)
end=$(( $(date +%s) + SECONDS_ ))
x=700; dx=6
while [ "$(date +%s)" -lt $end ]; do
  x=$((x + dx)); [ $x -gt 820 ] && dx=-6; [ $x -lt 580 ] && dx=6
  xdotool mousemove $x 400; sleep 0.02
done
end_lines=$(grep -c '^frame ' "$log"); t1=$(date +%s.%N)
case $scenario in
  orbit*) xdotool mouseup 1 keyup alt ;;
  drag*) xdotool key Escape ;;
esac
sleep 0.5; kill $pid; wait $pid 2>/dev/null
sed -n "$((start_lines + 1)),${end_lines}p" <(grep '^frame ' "$log") > "$WORK/$scenario.frames"
echo "$scenario $start_lines $end_lines $t0 $t1"
SH

summary() {  # scenario frames-file t0 t1
  awk -v name="$1" -v t0="$3" -v t1="$4" '
    { n++; for (i = 3; i <= NF; i++) { split($i, kv, "="); k = kv[1]; v = kv[2];
        if (k == "draw_ms") { m = split(v, d, ","); s = 0; for (j = 1; j <= m; j++) s += d[j]; sum["draw"] += s; panes = m }
        else sum[k] += v } }
    END { if (!n) { printf "%-14s no frames\n", name; exit }
      printf "%-14s %5.2f fps  frame %6.1f  deform %6.1f (%d%%)  normals %5.1f  upload %5.1f  draw %6.1f (%d panes)  ui %5.1f  quantities %5.1f  swap %5.1f  deforms/frame %.2f  uploads/frame %.2f\n",
        name, n / (t1 - t0), sum["total_ms"] / n, sum["deform_ms"] / n, 100 * sum["deform_ms"] / sum["total_ms"],
        sum["normals_ms"] / n, sum["upload_ms"] / n, sum["draw"] / n, panes, sum["ui_ms"] / n,
        sum["measure_ms"] / n, sum["swap_ms"] / n, sum["deforms"] / n, sum["uploads"] / n }' "$2"
}

echo "# $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg)"
for scenario in ${SCENARIOS:-orbit drag orbit3 drag3}; do
  extra=()
  case $scenario in *3) extra=(--view somigliana --view somigliana:nu=0 --view somigliana:nu=0.45) ;; esac
  line=$(WORK=$work EXE=$exe FH=$fh SECONDS_=$seconds xvfb-run -a -s '-screen 0 1000x700x24' \
         bash "$work/run.sh" "$scenario" "${extra[@]}" | tail -1)
  read -r name _ _ t0 t1 <<< "$line"
  summary "$name" "$work/$name.frames" "$t0" "$t1"
done
echo "# load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
