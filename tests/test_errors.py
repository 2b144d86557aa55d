"""Errors arrive whole from dask workers: every field survives pickling."""

import pickle

from pipeline.errors import LayoutError, SpecimensError


def test_an_error_keeps_its_fields_through_pickle():
    error = LayoutError("no table", file="a.csv", row=3, column="Force", hint="look")
    copy = pickle.loads(pickle.dumps(error))
    assert type(copy) is LayoutError and str(copy) == str(error)
    assert (copy.file, copy.row, copy.column, copy.hint) == ("a.csv", 3, "Force", "look")


def test_the_specimens_a_file_holds_survive_pickle():
    error = SpecimensError("2 specimens", specimens=["S1", "S2"], file="b.csv", row=2,
                           hint="say which")
    copy = pickle.loads(pickle.dumps(error))
    assert type(copy) is SpecimensError and isinstance(copy, LayoutError)
    assert copy.specimens == ["S1", "S2"] and str(copy) == str(error)
