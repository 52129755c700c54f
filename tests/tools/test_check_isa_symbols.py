"""check_isa_symbols.py on two small archives: one whose per-ISA object defines only symbols in its namespace, one
whose object also defines an inline function outside it (a weak symbol, as an unwrapped header would give)."""
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

CHECKER = Path(__file__).resolve().parents[2] / "tools" / "check_isa_symbols.py"
INLINE = "inline int f(int x) { return x + 1; }"
USE = "int g(int x) { return f(x); }"
CLEAN = f"namespace somicage {{ inline namespace isa_x86_64_v3 {{ {INLINE} {USE} }} }}\n"
LEAKY = f"namespace somicage {{ {INLINE} inline namespace isa_x86_64_v3 {{ {USE} }} }}\n"


def archive(tmp_path, source):
    cpp = tmp_path / "somigliana_row_kernels_x86_64_v3.cpp"
    cpp.write_text(source)
    obj = tmp_path / "somigliana_row_kernels_x86_64_v3.cpp.o"
    subprocess.run(["g++", "-O0", "-c", str(cpp), "-o", str(obj)], check=True)
    lib = tmp_path / "libtest.a"
    subprocess.run(["ar", "rcs", str(lib), str(obj)], check=True, cwd=tmp_path)
    return lib


@pytest.mark.skipif(not shutil.which("g++") or not shutil.which("nm"), reason="needs g++ and nm")
@pytest.mark.parametrize("source, code", [(CLEAN, 0), (LEAKY, 1)])
def test_flags_symbols_outside_the_copys_namespace(tmp_path, source, code):
    result = subprocess.run([sys.executable, str(CHECKER), str(archive(tmp_path, source))], capture_output=True,
                            text=True)
    assert result.returncode == code, result.stdout
