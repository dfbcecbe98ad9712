"""The example scripts run and write their charts (python/examples)."""

import importlib.util
import pathlib

EXAMPLES = pathlib.Path(__file__).resolve().parent.parent / "examples"


def test_speed_mass_map_writes_a_png(tmp_path):
    spec = importlib.util.spec_from_file_location("speed_mass_map", EXAMPLES / "speed_mass_map.py")
    example = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(example)
    output = tmp_path / "map.png"
    example.main(str(output))
    assert output.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
