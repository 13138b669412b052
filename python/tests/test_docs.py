# Copyright 2026 the Spherekit Authors
# SPDX-License-Identifier: Apache-2.0 OR MIT
"""The examples in the docstrings run (native and Python ones alike)."""

import doctest
import importlib.metadata
import inspect
import re

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


def public_callables():
    """Every public function, class and method of the package, by name."""
    for name in spherekit.__all__:
        obj = getattr(spherekit, name)
        yield name, obj
        if inspect.isclass(obj):
            for attr, member in vars(obj).items():
                if callable(member) and (not attr.startswith("_") or attr == "__call__"):
                    yield f"{name}.{attr}", member


@pytest.mark.parametrize("name,obj", sorted(public_callables(), key=lambda p: p[0]), ids=lambda v: v if isinstance(v, str) else "")
def test_signatures_are_visible_to_help(name, obj):
    """help() and Jupyter show the real parameters (pyo3 `signature`s), not `(*args, **kwargs)`."""
    import pydoc

    signature = inspect.signature(obj)  # ValueError for a native callable without one
    kinds = {p.kind for p in signature.parameters.values()} - {inspect.Parameter.POSITIONAL_ONLY}
    assert kinds != {inspect.Parameter.VAR_POSITIONAL, inspect.Parameter.VAR_KEYWORD}, f"{name}{signature}"
    shown = pydoc.render_doc(obj, renderer=pydoc.plaintext)
    parameters = [p for p in signature.parameters if p != "self"]
    assert all(p in shown for p in parameters), f"help({name}) does not show {signature}"


def test_the_version_is_the_crates():
    assert re.fullmatch(r"\d+\.\d+\.\d+", spherekit.__version__)
    assert importlib.metadata.version("spherekit") == spherekit.__version__
