"""The string bed: a pre-tensioned orthotropic membrane on the head (scikit-fem), its materials,
static stiffness and fixed-edge modes at impact points."""
