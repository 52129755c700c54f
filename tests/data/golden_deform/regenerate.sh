#!/bin/sh
# Writes NAME.obj for each case of cases.txt with the somicage executable given: ./regenerate.sh PATH/TO/somicage.
# Only with the executable of the commit README.md names (the outputs are what that commit wrote).
set -eu
exe=$1
here=$(cd "$(dirname "$0")" && pwd)
grep -v '^#' "$here/cases.txt" | while read -r name dim flags; do
  if [ "$dim" = 3 ]; then cage=$here/../cube_cage.obj; else cage=$here/../l_shape_loop.obj; fi
  # shellcheck disable=SC2086  # the flags are words
  "$exe" deform --cage "$cage" --posed "$here/posed${dim}d.obj" --mesh "$here/mesh${dim}d.obj" \
    --out "$here/$name.obj" $flags
done
