#!/usr/bin/env bash
# Renders the paper's figures and the user guide's screenshots into DIR (docs/gallery for the committed set):
#   tools/figures.sh DIR [NAME...]
# The editor draws them headless under Xvfb (Mesa llvmpipe); tools/figures.py says what each figure is.
# SOMICAGE=path/to/somicage picks the executable (default build/app/somicage), SOMICAGE_MODELS the models folder
# (default ../shared/models; figures whose model is absent are skipped with a line saying so).
# Debian's /usr/bin/python3: its python3-numpy, python3-matplotlib and python3-pil (third_party/install-deps.sh).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
exec xvfb-run -a -s "-screen 0 1920x1080x24" /usr/bin/python3 "$here/figures.py" "$@"
