"""`help()` reads as documentation, and the examples in it run."""

from __future__ import annotations

import doctest
import pydoc

import slider_crank as sc


def test_every_public_name_is_documented() -> None:
    for name in sc.__all__:
        item = getattr(sc, name)
        # the type aliases Point and Centre are documented by `#:` comments
        # in the source (a typing alias carries no docstring of its own)
        if callable(item) and getattr(item, "__module__", None) != "typing":
            assert item.__doc__ and len(item.__doc__) > 60, name
    for method in ("at", "sweep", "figure", "handout", "exercise", "turning_moment",
                   "curved_slot", "inversion"):
        assert getattr(sc.SliderCrank, method).__doc__, method


def test_help_on_slider_crank_explains_the_engine() -> None:
    text = pydoc.render_doc(sc.SliderCrank, renderer=pydoc.plaintext)  # type: ignore[attr-defined]
    for phrase in ("crank radius", "ValueError", "at(self, theta_deg", "analyze",
                   "GIL released", "rpm"):
        assert phrase in text, phrase


def test_the_examples_in_the_docstrings_hold() -> None:
    result = doctest.testmod(sc, optionflags=doctest.ELLIPSIS)
    assert result.attempted >= 3 and result.failed == 0
