"""The examples in the docstrings run and print what they say."""

import doctest

import numpy as np
import pytest

import weft
from weft import _interop, _lib, _mesh, _ops


@pytest.mark.parametrize("module", [weft, _lib, _mesh, _ops, _interop], ids=lambda m: m.__name__)
def test_docstring_examples(module):
    results = doctest.testmod(
        module, extraglobs={"weft": weft, "np": np}, optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE, report=True
    )
    assert results.attempted > 0
    assert results.failed == 0, f"{results.failed} docstring examples of {module.__name__} failed (printed above)"
