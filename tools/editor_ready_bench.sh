#!/usr/bin/env bash
# Time to first frame of the editor on FIREHYDRANT (issue 27, docs/editor.md "Time to the first frame"), next to the
# CLI's precompute on the same machine: `somicage bench`'s precompute_s (median of 3), then RUNS editors opened on
# the mesh and cage under Xvfb (llvmpipe), each line of --log-actions / --log-frames stamped as it arrives. Prints
# per run: the seconds from launch to the editor's first frame (the window open), from there to the first frame that
# draws the mesh and to "ready" (the precompute's outcome installed), and the precompute worker's own seconds (its
# request: reading the files, the memory check, the coordinates).
#   tools/editor_ready_bench.sh BUILD_DIR [MODELS_DIR] [RUNS]
set -euo pipefail
build=${1:?usage: editor_ready_bench.sh BUILD_DIR [MODELS_DIR] [RUNS]}
models=${2:-$(cd "$(dirname "$0")/../.." && pwd)/shared/models}
runs=${3:-3}
exe=$(cd "$build" && pwd)/app/somicage
mesh=$models/firehydrant/fireHydrant.obj
cage=$models/firehydrant/fireHydrant_cages_triangulated.obj
[ -f "$mesh" ] || { echo "FIREHYDRANT not found in $models" >&2; exit 1; }
work=$(mktemp -d)
[ -n "${KEEP:-}" ] && echo "work: $work" >&2 || trap 'rm -rf "$work"' EXIT

echo "# $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg), $exe"
cli=$("$exe" bench --mesh "$mesh" --cage "$cage" --frames 3 --repeat 3 --baseline-points 50 --method somigliana \
      --json 2>/dev/null | grep -o '"precompute_s": *[0-9.e+-]*' | head -1 | sed 's/.*: *//')
echo "cli precompute_s $cli"

cat > "$work/run.sh" <<'SH'
set -u
mkdir -p "$WORK/config"
{ printf '%s launch\n' "$(date +%s.%N)"
  XDG_CONFIG_HOME=$WORK/config "$EXE" --size 1000x700 --log-actions --log-frames "$MESH" "$CAGE" 2>/dev/null |
    while IFS= read -r line; do printf '%s %s\n' "$(date +%s.%N)" "$line"; done; } > "$WORK/log" &
for i in $(seq 1 1200); do grep -q ' job precompute' "$WORK/log" 2>/dev/null && break; sleep 0.05; done
sleep 0.5; xdotool key ctrl+q; sleep 1; xdotool key d 2>/dev/null; wait
SH
for r in $(seq 1 "$runs"); do
  WORK=$work EXE=$exe MESH=$mesh CAGE=$cage xvfb-run -a -s '-screen 0 1000x700x24' bash "$work/run.sh" || true
  awk '
    $2 == "launch" { launch = $1 }
    $2 == "frame" && !first { first = $1 }
    $2 == "frame" && !mesh && $0 !~ / mesh_draws=0/ { mesh = $1 }
    $2 == "job" && $3 == "precompute" && !ready { ready = $1; secs = $4 }
    END { if (!ready) { print "run: no precompute in the log"; exit }
      printf "run: window (first frame) %.2f s after launch; then the mesh drawn after %.2f s, ready after %.2f s (worker %s s)\n",
             first - launch, mesh - first, ready - first, secs }' "$work/log"
done
echo "# load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
