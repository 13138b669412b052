# Copyright 2026 the Spherekit Authors
# SPDX-License-Identifier: Apache-2.0 OR MIT
"""The examples in the docstrings run (native and Python ones alike)."""

import doctest
import inspect

import pytest

import spherekit
from spherekit import _scipy, _spherekit


def documented():
    """Every documented module, class and function of the package, once."""
    seen = {}
    for module in (spherekit, _scipy, _spherekit):
        seen.setdefault(id(module), (module.__name__, module))
        for name, obj in vars(module).items():
            ours = getattr(obj, "__module__", "").startswith("spherekit")
            if not name.startswith("__") and ours and (inspect.isclass(obj) or callable(obj)):
                seen.setdefault(id(obj), (f"{obj.__module__}.{name}", obj))
    return {name: obj for name, obj in seen.values() if ">>>" in (obj.__doc__ or "")}


DOCUMENTED = documented()


def test_every_public_name_has_an_example():
    documented = {id(obj) for obj in DOCUMENTED.values()}
    missing = [n for n in spherekit.__all__ if id(getattr(spherekit, n)) not in documented]
    assert not missing


@pytest.mark.parametrize("name", sorted(DOCUMENTED))
def test_docstring_examples(name):
    test = doctest.DocTestParser().get_doctest(DOCUMENTED[name].__doc__, {}, name, None, 0)
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS)
    runner.run(test)
    assert runner.failures == 0 and runner.tries > 0
