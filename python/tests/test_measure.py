"""covopt.predict_measurement: what a biofidelic measuring device reads beside the body model
(docs/guide/limits.md). The result is ``covopt measure --json``'s object; the reading is
checked against an independent numpy closed form of a Hertz sphere on the pad in series with
the device's spring; the trends (softer pad reads less, the fixed device more than a recoiling
region) and the refusals naming the keyword."""

import json
import math
import pathlib

import numpy as np
import pytest

import covopt
from conftest import without_provenance

BARE = {"covering_thickness": 0, "robot_mass": "10kg", "speed": "0.25m/s", "robot_radius": "50mm"}


def closed_form(m, v, k, radius, shore, nu=0.49):
    """m v²/2 = F²/(2k) + 2/5 K^(-2/3) F^(5/3), K = 4/3 E/(1-nu²) sqrt(R), by bisection."""
    E = 1e6 * 10 ** (0.0235 * shore - 0.6403)
    K = 4.0 / 3.0 * E / (1 - nu * nu) * math.sqrt(radius)
    lo, hi = 0.0, v * math.sqrt(m * k)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if mid * mid / (2 * k) + 0.4 * (mid / K) ** (2 / 3) * mid < 0.5 * m * v * v:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def test_same_object_as_the_cli(cli):
    r = covopt.predict_measurement(covopt.Scene(**BARE), body_region="chest", contact_area="1cm2",
                                   device_spring="25N/mm", device_pad="70ShA,7mm")
    code, out, err = cli("measure", "--body-region", "chest", "--contact-area", "1cm2", "--covering-thickness", "0",
                         "--robot-mass", "10kg", "--speed", "0.25m/s", "--robot-radius", "50mm",
                         "--device-spring", "25N/mm", "--device-pad", "70ShA,7mm", "--json")
    assert code == 0, err
    assert without_provenance(r) == without_provenance(json.loads(out))
    assert r.summary.command == "measure"
    assert "input_sources" in r.to_dict()


def test_reading_is_the_closed_form():
    for shore, k in ((70, 25e3), (30, 35e3), (10, 10e3)):
        r = covopt.predict_measurement(covopt.Scene(**BARE), body_region="chest", contact_area="1cm2",
                                       device_spring=k, device_pad=f"{shore}ShA,7mm")
        assert r.device.peak_force_N == pytest.approx(closed_form(10.0, 0.25, k, 0.05, shore), rel=1e-9)
        assert r.device.reduced_mass_kg == 10.0
        assert r.device.stiff_pad_force_N == pytest.approx(0.25 * math.sqrt(10.0 * k))
        assert r.device.peak_force_N < r.device.stiff_pad_force_N


def test_trends_and_the_default_device():
    forces = [covopt.predict_measurement(covopt.Scene(**BARE), body_region="chest", contact_area="1cm2",
                                         device_spring="25N/mm", device_pad=f"{h}ShA,7mm").device.peak_force_N
              for h in (30, 50, 70, 90)]
    assert np.all(np.diff(forces) > 0)  # a softer pad reads less
    r = covopt.predict_measurement(covopt.Scene(**BARE), body_region="chest", contact_area="1cm2")
    assert r.device.name == "25+70" and r.device.pad_thickness_assumed
    assert any("7 mm assumed" in w for w in r.warnings)
    # the fixed device (mu = 10 kg) against the chest's recoiling 40 kg (mu = 8 kg), nearly rigid pad
    stiff = covopt.predict_measurement(covopt.Scene(**{**BARE, "robot_radius": "200mm"}), body_region="chest",
                                       contact_area="1cm2", device_spring="25N/mm", device_pad="100ShA,2mm")
    assert stiff.comparison.force_ratio > 1.0
    assert stiff.body_model.reduced_mass_kg == pytest.approx(8.0)


@pytest.mark.parametrize("keywords, named", [
    ({"device_spring": 0, "device_pad": "70ShA"}, "device_spring"),
    ({"device_spring": "25N/mm", "device_pad": "170ShA"}, "device_pad"),
    ({"device_spring": "25N/mm", "device_pad": "70ShA,0mm"}, "device_pad"),
    ({"device_spring": "25N/mm"}, "device_pad"),
    ({"device": "elbow"}, "device: unknown preset 'elbow'"),
    ({"device": "25+70", "device_pad_thickness": "50cm"}, "device_pad_thickness"),
])
def test_bad_devices_are_refused(keywords, named):
    with pytest.raises(ValueError, match=named.replace("+", r"\+")):
        covopt.predict_measurement(covopt.Scene(**BARE), body_region="chest", contact_area="1cm2", **keywords)


def test_report(tmp_path):
    r = covopt.predict_measurement(covopt.Scene(**BARE), body_region="chest", contact_area="1cm2")
    html = pathlib.Path(r.to_html(tmp_path / "measure.html")).read_text(encoding="utf-8")
    assert "chest (sternum), device 25+70" in html and "chest (sternum), body model" in html
