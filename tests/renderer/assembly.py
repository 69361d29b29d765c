"""What the tests read in a kernel's assembly (numba's ``inspect_asm``, AT&T order)."""
from __future__ import annotations

import re

SCALAR_INT64_TO_FLOAT = re.compile(r"^\s*vcvtsi2s[sd]q?\s+%r\w+,", re.MULTILINE)
"""A scalar conversion of a 64-bit integer register to float: AVX2 has no vector instruction
for it, so a vector loop that converts int64 lanes converts each one alone."""


def scalar_int64_conversions(kernel) -> list[str]:
    """The scalar int64 → float conversions in every compiled version of the numba ``kernel``."""
    return SCALAR_INT64_TO_FLOAT.findall("\n".join(kernel.inspect_asm().values()))
