"""Reference cases: the product's outputs against independent references (literature, standards, published
tables), one function per case returning what it measured. The validation tests (tests/validation) assert on
these functions and `make report` renders them as its first table (benchmarks/reference_table.py): the
report shows the very numbers the tests check and cannot drift from them.

The cases belong to the tests, which own the validation; the report imports them from here. They are not in the
installed package: the report runs from a checkout, and several cases read the transcribed sources in
tests/validation/data/ or use the reference twins of tests/reference/.
"""

from .comparison import Comparison, ReferenceCase, outside, worst
from .registry import CASES

__all__ = ["CASES", "Comparison", "ReferenceCase", "outside", "worst"]
