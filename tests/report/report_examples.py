# SPDX-License-Identifier: MIT
"""The examples whose reports the browser and LaTeX tests open: one per feature of a report.
The other examples' pages repeat what these show, and each report runs its whole script."""

FEATURES = {
    "sit_to_stand": "a planar model: torques solved, plotted and animated (the main example)",
    "four_bar_linkage": "a closed loop: constraint rows beside the free-body diagrams",
    "inverted_pendulum_cart": "a sliding joint, a linearization and a simulation",
    "kuka_iiwa": "a spatial arm, its equations past the size that is folded and abbreviated",
    "rolling_disk": "rolling: Kane's equations with motion constraints, the 3D view",
    "statics_double_pendulum": "statics: springs, no motion",
    "triple_pendulum_fall": "a simulation animated, energy checked",
}
