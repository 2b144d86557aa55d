"""The published models, one module per paper, as pure vectorised functions.

=====================  ======  ==================================================
module                 paper   what it computes
=====================  ======  ==================================================
``link_stiffness``     001     static stiffness E0 of round-link chains (Rynik)
``wheel_impact``       000     impact velocities and tensions on a pocket wheel
``roller_impact``      002     impact of roller chains on sprockets (xi, n_max)
``tooth_segments``     003     loads on segmented teeth of a chain drum
``pin_criterion``      004     pin criterion for roller chains of open drives
=====================  ======  ==================================================

The models read no files; inputs are SI unless a name carries its unit. Each
module's ``compare_published()`` reads its paper's published numbers from
``pipeline/data/published/paper_<paper>.csv`` and sets the model's value
beside each, by the one tolerance rule of ``_published``. Each module's
``table()`` gives the rows its ``chainbench theory`` command prints, in the
units their keys name (the command only parses its options and prints).
"""
