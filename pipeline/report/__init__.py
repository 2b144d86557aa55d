"""The campaign report: figures (matplotlib) arranged by a jinja2 template.

Figures are built by functions that take data (xarray datasets) and return a
:class:`matplotlib.figure.Figure`; :func:`pipeline.report.render.svg` turns one
into deterministic inline SVG; the builder only arranges them.
"""
