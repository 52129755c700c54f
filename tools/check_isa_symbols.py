#!/usr/bin/env python3
"""Checks that the per-ISA copies of the row kernels share no symbol (docs/performance.md).

Usage: check_isa_symbols.py LIBRARY.a

Every object compiled from core/coordinates/somigliana_row_kernels_isa.cpp (somigliana_row_kernels_ISA.cpp.o in the
archive) may define global or weak symbols only inside its own namespace, somicage::isa_ISA. A weak symbol outside it
(an inline function or template of a header that is not wrapped in SOMICAGE_ISA_BEGIN/END) would be merged by the
linker with the other copies' and the baseline code's, so the AVX2 copy could run on a CPU without AVX2.
Exit 0 when clean, 1 with the offending symbols listed.
"""
import re
import subprocess
import sys

# "library:member:address type name"
LINE = re.compile(r"^.*:somigliana_row_kernels_(\w+)\.cpp\.o:\s*[0-9a-fA-F]*\s+(\S)\s+(.*)$")


def main(library):
    listing = subprocess.run(["nm", "-C", "-A", "--defined-only", library], check=True, capture_output=True,
                             text=True).stdout
    copies, bad = set(), []
    for line in listing.splitlines():
        match = LINE.match(line)
        if not match:
            continue
        isa, kind, name = match.groups()
        copies.add(isa)
        if kind.islower() and kind not in ("w", "v", "u"):
            continue  # local to the object
        if f"somicage::isa_{isa}::" not in name:
            bad.append(f"{isa}: {kind} {name}")
    if not copies:
        print(f"{library}: no per-ISA objects (somigliana_row_kernels_*.cpp.o) found")
        return 1
    if bad:
        print("symbols of the per-ISA copies outside their own namespace (shared with other copies):")
        print("\n".join(bad))
        return 1
    print(f"per-ISA copies {sorted(copies)}: every global or weak symbol is in its own namespace")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
