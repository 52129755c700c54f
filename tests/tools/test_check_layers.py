"""tools/check_layers.py: the real core passes, and a made-up core with each kind of violation is caught."""
import pathlib
import subprocess
import sys

REPO = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(REPO / "tools"))
import check_layers  # noqa: E402


def write(root, path, *includes):
    file = root / "core" / path
    file.parent.mkdir(parents=True, exist_ok=True)
    file.write_text("".join(f'#include "{name}"\n' for name in includes) + "int x;\n")


def test_the_repository_core_keeps_its_layers():
    result = subprocess.run([sys.executable, str(REPO / "tools/check_layers.py"), str(REPO)], capture_output=True,
                            text=True)
    assert result.returncode == 0, result.stdout


def test_a_layered_core_passes(tmp_path):
    write(tmp_path, "base/errors.h")
    write(tmp_path, "geometry/cage.h", "base/errors.h")
    write(tmp_path, "geometry/cage.cpp", "geometry/cage.h", "base/errors.h", "method_list.inc")
    write(tmp_path, "engine/engine.h", "geometry/cage.h")
    assert check_layers.check(str(tmp_path / "core")) == []


def test_an_upward_include_is_reported_with_its_line(tmp_path):
    write(tmp_path, "engine/engine.h")
    write(tmp_path, "base/json.h", "base/errors.h", "engine/engine.h")
    write(tmp_path, "base/errors.h")
    problems = check_layers.check(str(tmp_path / "core"))
    assert len(problems) == 1 and problems[0].startswith("core/base/json.h:2: includes engine/engine.h")


def test_folders_of_one_layer_may_not_include_each_other(tmp_path):
    write(tmp_path, "cage/cage_check.h", "deform/deformer.h")
    write(tmp_path, "deform/deformer.h")
    problems = check_layers.check(str(tmp_path / "core"))
    assert len(problems) == 1 and "not below 'cage'" in problems[0]


def test_an_include_without_its_folder_and_a_loose_file_are_reported(tmp_path):
    write(tmp_path, "base/errors.h")
    write(tmp_path, "base/json.h", "errors.h")
    write(tmp_path, "loose.cpp")
    write(tmp_path, "gadgets/thing.h")
    problems = check_layers.check(str(tmp_path / "core"))
    assert any('core/base/json.h:1: includes "errors.h" without its folder' == p for p in problems)
    assert any(p.startswith("core/loose.cpp: a source file outside every folder") for p in problems)
    assert any("folder 'gadgets' is in no layer" in p for p in problems)
    assert len(problems) == 3


def test_an_include_cycle_is_reported(tmp_path):
    write(tmp_path, "deform/a.h", "deform/b.h")
    write(tmp_path, "deform/b.h", "deform/c.h")
    write(tmp_path, "deform/c.h", "deform/a.h")
    problems = check_layers.check(str(tmp_path / "core"))
    assert problems == ["core/deform/a.h: include cycle deform/a.h -> deform/b.h -> deform/c.h -> deform/a.h"]
