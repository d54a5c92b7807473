"""Rotor finite-element model of a spindle shaft (docs/shaft.md): Timoshenko beam elements with the axial bar,
rigid disks and bearing seats taking a bearing's 5x5 stiffness and damping."""

from .model import ShaftInputError, ShaftModel, shaft_path
from .transient import ShaftTransient

__all__ = ["ShaftInputError", "ShaftModel", "ShaftTransient", "shaft_path"]
