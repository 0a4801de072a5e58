"""The general integrator for any contact law: the frame as an impact-point receptance, the force
as a piecewise cubic, the step, the march and the all-nodes solve."""
