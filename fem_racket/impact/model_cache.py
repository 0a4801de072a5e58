"""Assembled frames kept per process, so repeated impacts on one frame reuse its modes.

``frame_model(frame, elements)`` returns the same :class:`~fem_racket.frame.model.FrameModel`
(assembly and the free-free modes it has computed) for equal frames: a :class:`Frame` by value,
a :class:`FrameMesh` by its nodes and cell data, the standard racket for None. A FrameModel is
returned as it is. The last :data:`SIZE` frames are kept.
"""

from __future__ import annotations

from collections import OrderedDict
from typing import Any

from fem_racket.frame.mesh import FrameMesh
from fem_racket.frame.model import FrameModel
from fem_racket.frame.segments import Frame
from fem_racket.validation import InputError, check_integer

__all__ = ["clear_models", "frame_model"]

#: Frames kept per process.
SIZE = 16

_MODELS: OrderedDict[tuple, FrameModel] = OrderedDict()


def clear_models() -> None:
    """Forget the frames kept in this process."""
    _MODELS.clear()


def _key(frame: Any, elements: int) -> tuple:
    if frame is None or isinstance(frame, Frame):
        return ("frame", frame, elements)
    if isinstance(frame, FrameMesh):
        return ("mesh", frame.points.tobytes(), frame.EI.tobytes(), frame.rhoA.tobytes())
    raise InputError(
        f"frame = {frame!r} is not allowed: must be a Frame, a FrameMesh or a FrameModel"
    )


def frame_model(frame: Any, elements: int = 20) -> FrameModel:
    """The assembled model of ``frame`` (meshed with ``elements`` cells), built once per process."""
    if isinstance(frame, FrameModel):
        return frame
    if isinstance(frame, Frame) or frame is None:
        check_integer("elements", elements)
    key = _key(frame, elements)
    model = _MODELS.get(key)
    if model is None:
        model = FrameModel.build(frame, elements)
        _MODELS[key] = model
        if len(_MODELS) > SIZE:
            _MODELS.popitem(last=False)
    else:
        _MODELS.move_to_end(key)
    return model
