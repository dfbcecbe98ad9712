"""covopt.optimize's default answer: a band material's recommendation carries the range it
holds over; a scene no material can serve carries the nearest changes, each a change of the
verdict (the same keys as `covopt optimize --json`)."""

import covopt
from calls import call

BAND = "neoprene sponge D1056 2C3"  # sigma(25 %) band 62.1-89.6 kPa
VN600 = "vinyl-nitrile foam VN600"  # rate factor 1-4


def test_a_band_recommendation_holds_over_its_band():
    r = call(covopt.optimize, materials=BAND, speed=1.2)
    assert r["recommendation"]["material"] == BAND
    mr = r["material_range"]
    assert mr["admissible"] is True
    assert mr["thickness_m"] == r["recommendation"]["thickness_m"]
    assert mr["range"]["stated"] is True
    assert mr["range"]["scale_low"] < 1.0 < mr["range"]["scale_high"]
    assert [v["scale"] for v in mr["verdicts"]] == [mr["range"]["scale_low"], mr["range"]["scale_high"]]
    assert all(v["verdict"]["safe"] for v in mr["verdicts"])
    assert mr["worst_margin"] >= 0.0
    assert r["nearest_changes"] is None


def test_no_material_works_and_the_nearest_changes_are_named():
    r = call(covopt.optimize, materials=[BAND, VN600], speed=3.0)
    assert r["recommendation"] is None
    assert r["material_range"] is None
    assert "No catalog material works for this scene; nearest changes for" in r["message"]
    n = r["nearest_changes"]
    assert n["material"] in (BAND, VN600)
    assert n["at_thickness_m"] == r["design_space"]["max_thickness_m"]
    assert n["speed_m_per_s"]["reachable"] is True
    assert 0.0 < n["speed_m_per_s"]["value"] < 3.0
    # Just below the nearest speed the same material is recommended at the maximum thickness or less.
    slower = call(covopt.optimize, materials=n["material"], speed=n["speed_m_per_s"]["value"] * (1 - 1e-6))
    assert slower["recommendation"] is not None
    assert slower["recommendation"]["thickness_m"] <= n["at_thickness_m"]
    for c in r["candidates"]:
        assert c["range_note"].startswith("not admissible over ")
