"""The paper's closed forms: clamped and rigid frame (eqs 1-12), the coupled modes and the modal
split of the ball velocity (eqs 13-16)."""
