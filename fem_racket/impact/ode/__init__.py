"""Time integration of the coupled ODE: CVODE (scikit-sundae) and scipy BDF for the linear system,
CVODE for any contact law."""
