"""Assertions for a user's tests (docs/python-conformance.md).

    from hinge.testing import assert_conforms

    def test_my_bending_kernel():
        assert_conforms(my_kernel, tier="policy", stencil=("x0", "x3", "x1", "x2"))
"""

from .conformance import conform

__all__ = ["assert_conforms", "TIERS"]

# Best first (docs/conformance.md, "Tiers"); "approximate" and "fail" are not passed.
TIERS = ("correctly-rounded", "faithful", "4u", "policy", "approximate", "fail")


def assert_conforms(fn, tier="policy", **options):
    """Raises AssertionError carrying the text report unless every category reaches `tier`.

    `options` are those of hinge.conform (outputs, stencil, dtype, batch, depth). `tier` one of
    "correctly-rounded", "faithful", "4u", "policy" (the default: within the tolerance policy) or
    "approximate"; ValueError for another. Returns the report when it passes.
    """
    if tier not in TIERS[:-1]:
        raise ValueError(f"tier= must be one of {', '.join(repr(t) for t in TIERS[:-1])}; got {tier!r}")
    report = conform(fn, **options)
    wanted = TIERS.index(tier)
    short = [name for name, c in report.categories.items() if TIERS.index(c["tier"]) > wanted]
    if short:
        raise AssertionError(f"{len(short)} categor{'y' if len(short) == 1 else 'ies'} below tier {tier!r} "
                             f"({', '.join(short)})\n{report}")
    return report
