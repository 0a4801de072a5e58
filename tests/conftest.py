"""Shared fixtures: the paper's standard and rigid frames, assembled once per session."""

import pytest

from fem_racket import FrameModel, rigid_frame, standard_frame


@pytest.fixture(scope="session")
def standard_model() -> FrameModel:
    """The paper's standard racket, 20 elements (section 2.3)."""
    return FrameModel.build(standard_frame(), 20)


@pytest.fixture(scope="session")
def rigid_model() -> FrameModel:
    """The paper's 'rigid' racket, EI1 = 9999 N m^2, 20 elements."""
    return FrameModel.build(rigid_frame(), 20)
