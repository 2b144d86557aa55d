"""The stiffness overview of the campaign page: one panel per chain, a tick per specimen."""

import io
import warnings

import numpy as np
import xarray as xr

from pipeline.report.stiffness_figures import MAX_LABEL_CHARS, stiffness_by_specimen


def summary() -> xr.Dataset:
    interval = {"confidence_level": 0.95}
    values = {"E0_theory": 20e6, "E0_exp": 21e6, "E0_exp_ci_low": 20.5e6,
              "E0_exp_ci_high": 21.5e6}
    return xr.Dataset(
        {name: ("chain", [value], interval if "ci" in name else {})
         for name, value in values.items()},
        coords={"chain": ["c18x64"]}, attrs={"band": "0.03 0.06"})


def run(specimen: str, e0: float) -> xr.Dataset:
    fits = {name: (("cycle", "branch"), [[e0 * factor]])
            for name, factor in (("fit_E0", 1.0), ("fit_E0_ci_low", 0.99),
                                 ("fit_E0_ci_high", 1.01))}
    return xr.Dataset(fits | {"single_pull": ((), 1)},
                      coords={"cycle": [1], "branch": ["loading"]},
                      attrs={"chain": "c18x64", "specimen": specimen})


def tick_labels(figure) -> list[str]:
    return [label.get_text() for label in figure.axes[0].get_xticklabels()]


def test_specimens_named_after_their_files_fit_the_axis():
    # ids drafted from file names: drawn whole, they took the figure's whole width and
    # matplotlib gave up its layout ("axes sizes collapsed to zero") with a warning
    names = [f"Lab__Tensile-Campaign__{day}_Specimen_RawData_{number}"
             for day, number in (("Mon", 1), ("Tue", 2), ("Wed", 3), ("Thu", 4))] + ["18-A"]
    figure = stiffness_by_specimen(summary(), [run(name, 21e6) for name in names])
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        figure.savefig(io.BytesIO(), format="svg")
    labels = tick_labels(figure)
    assert len(labels) == 5 and labels[-1] == "18-A"
    assert all(len(label) <= MAX_LABEL_CHARS for label in labels)
    assert labels[0].startswith("Lab__Ten") and labels[0].endswith("wData_1")
    assert len(set(labels)) == 5


def test_specimens_whose_shortened_names_coincide_are_counted_not_labelled():
    names = [f"Lab__Tensile-Campaign__{day}_Specimen_RawData_1" for day in ("Mon", "Tue")]
    figure = stiffness_by_specimen(summary(), [run(name, 21e6) for name in names])
    assert tick_labels(figure) == []
    assert figure.axes[0].get_xlabel() == "2 specimens, in the order of the run table"
    np.testing.assert_allclose(figure.axes[0].get_xlim(), (-0.6, 1.6))
