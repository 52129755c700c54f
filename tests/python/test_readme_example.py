"""docs/python.md's Python example runs as written (with the models folder this build was configured with)."""
import pathlib
import re

import numpy as np

from conftest import MODELS_DIR, require_firehydrant

README = pathlib.Path(__file__).parents[2] / "docs" / "python.md"


def test_readme_example_runs(capsys):
    require_firehydrant()
    example = re.search(r"<!-- python example -->\n```python\n(.*?)```", README.read_text(), re.S).group(1)
    assert len(example.strip().splitlines()) <= 10
    scope = {}
    exec(example.replace('"../shared/models/', f'"{MODELS_DIR}/'), scope)
    points, moved = scope["points"], scope["moved"]
    assert moved.shape == points.shape and np.isfinite(moved).all()
    assert np.abs(moved - points).max() > 1e-2 * np.ptp(points, axis=0).max()  # the pose moved the mesh
