#!/usr/bin/python3
"""Sanity check of polar_reference.py: reproduce the table of spec/math.md §3
(six-lobe example) to every printed digit.

Usage: /usr/bin/python3 check_math_md_table.py [SIX_LOBE_PROJECT]
(default: /work/shared/examples/six-lobe-arc-cam.cam.json)
"""

import sys
from decimal import Decimal

from mpmath import mpf

sys.dont_write_bytecode = True  # keep tests/reference free of __pycache__
import polar_reference as ref  # noqa: E402

DEFAULT_PROJECT = "/work/shared/examples/six-lobe-arc-cam.cam.json"

# t, phi, r, v_r, v_phi, a_r, a_phi exactly as printed in math.md §3.
TABLE = [
    ("0.05", "45",  "26.218824198", "-369.148280152", "411.844327435", "-40298.5214382", "-11597.1352501"),
    ("0.15", "135", "26.218824198", "369.148280152",  "411.844327435", "-40298.5214382", "11597.1352501"),
    ("0.37", "333", "28.897219241", "-61.829076850",  "453.916458381", "-25873.4168380", "-1942.4177361"),
    ("0.00", "0",   "20.896819450", "0",              "328.246472338", "22258.2712666",  "0"),
]
KEYS = ["phi_deg", "r", "v_r", "v_phi", "a_r", "a_phi"]


def rounded_like(value, printed):
    """value rounded to the number of decimals printed in the table."""
    exponent = Decimal(printed).as_tuple().exponent
    return Decimal(str(value)).quantize(Decimal(1).scaleb(exponent))


def main():
    project = ref.load_project(sys.argv[1] if len(sys.argv) > 1 else DEFAULT_PROJECT)
    ok = True
    for t, *printed_values in TABLE:
        state = ref.state_at(project, mpf(t))
        for key, printed in zip(KEYS, printed_values):
            ours = rounded_like(state[key], printed)
            match = ours == Decimal(printed)
            ok = ok and match
            print(f"t={t:5} {key:6} table {printed:>16}  reference {ours!s:>16}"
                  f"  {'ok' if match else 'MISMATCH'}")
    print("math.md §3 table reproduced to all printed digits" if ok else "FAILED")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
