"""Settings read from the processed files' attributes, refused when not recorded."""

from __future__ import annotations

import pytest

from pipeline.errors import ChainbenchError
from pipeline.report.recorded import level, recorded


def test_a_recorded_setting_is_read_as_written():
    assert recorded({"band": "0.03 0.06"}, "band") == "0.03 0.06"
    assert level({"confidence_level": 0.95}) == "95 %"
    assert level({"confidence_level": 0.683}) == "68.3 %"


def test_a_missing_setting_names_itself_and_how_to_get_it():
    with pytest.raises(ChainbenchError, match="'fit_window'") as caught:
        recorded({"title": "t"}, "fit_window")
    assert "chainbench run --force" in caught.value.hint
