"""KEYENCE NR-series logger exports: stamps to the second, the microseconds beside them."""

import numpy as np

from pipeline.ingest import read_table

# a real NR-500 export's header (shortened; our readings): the channel's unit in the
# header's 単位 line, the names in the #EndHeader line
HEADER = ("#BeginHeader,57\n#FormatType,NR-500\\NORMAL\n#FormatVersion,R3.00.00\n"
          "タイトル,\nユニット番号,MASTER,UNIT1\n\n計測モード,ノーマルモード\n"
          "収集開始日時,2023/05/08 16:16:51,579000\nサンプリング周期,50ms\n\n"
          "チャンネル条件,\nチャンネル番号,,(1)HA-V01\n波形名,,\"Voltage01\"\n"
          "単位,,\"{unit}\"\nスケーリング,,OFF\n\n#EndHeader,日時(μs),(1)HA-V01\n")


def _rows(count: int) -> str:
    """Rows 50 ms apart from 16:16:52.979, stamped to the second, the microseconds beside."""
    lines = []
    for row in range(count):
        micro = 979_000 + 50_000 * row
        lines.append(f"2023/05/08 16:16:{52 + micro // 1_000_000},{micro % 1_000_000:06d},"
                     f"{0.5 * row:.3f}")
    return "\n".join(lines) + "\n"


def test_the_time_is_the_stamp_plus_the_microseconds_beside_it(write):
    # read as a table, the microseconds were the time: it stepped back at every second
    path = write("instron.csv", HEADER.format(unit="kN") + _rows(60))
    table, meta = read_table(path, kind="engagement")
    assert meta.layout == "keyence" and meta.time_monotonic
    np.testing.assert_allclose(table["time"], 0.05 * np.arange(60), atol=1e-9)
    np.testing.assert_allclose(table["force"], 500.0 * np.arange(60))
    assert meta.preamble["サンプリング周期"] == "50ms"
    assert not any("steps back" in warning for warning in meta.warnings)
