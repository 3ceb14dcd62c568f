"""Analyses from Python against the program's output files for the same input: eigenvalues
against speed, the critical-speed studies, the K_ij study, the sweep and the assessment of a
run give the same numbers to the last bit."""
import numpy as np
import pytest

import ferrodyn
from conftest import SOURCE, cli, same_bits

HUNTING = "wheelset_hunting.yaml"
# Short settling so that each branch is a few seconds of simulated time.
SETTLE = {"segment": 2.0, "t_max": 4.0, "disturbance": 1e-3}
SETTLE_ARGS = ["--segment", "2", "--t-max", "4", "--disturbance", "1e-3"]


def test_eigenvalues_match_eig(scenes, tmp_path):
    out = tmp_path / "eig.h5"
    cli("eig", scenes / HUNTING, "--points", "25", "-o", out, "--no-plots")
    r = ferrodyn.analysis.eigenvalues(ferrodyn.Scene(scenes / HUNTING), points=25)
    f = ferrodyn.read(out)
    assert same_bits(r["speed"], f["/eigen/speed"])
    assert same_bits(r["damping_ratio"], f["/eigen/damping_ratio"])
    assert same_bits(r["frequency"], f["/eigen/frequency"])
    assert same_bits(r["eigenvalue"].real, f["/eigen/eigenvalue_real"])
    # The critical speed is the Hopf crossing; the suspended wheelset has the closed form (151).
    # The Jacobian is linearised by central differences: the crossing agrees to ~1e-8.
    assert r["critical_speed"] == pytest.approx(r["closed_form_critical_speed"], rel=1e-6)


def test_critical_speed_eigen_with_factors(scenes, tmp_path):
    out = tmp_path / "ceig.h5"
    cli("critical-speed", "eigen", scenes / HUNTING, "--points", "30", "--k11", "0.8", "--k22",
        "0.8", "-o", out, "--no-plots")
    r = ferrodyn.analysis.critical_speed_eigen(ferrodyn.Scene(scenes / HUNTING), k11=0.8,
                                               k22=0.8, points=30)
    assert same_bits(r["damping_ratio"], ferrodyn.read(out)["/eigen/damping_ratio"])


def test_ramp_matches_the_program(scenes, tmp_path):
    out = tmp_path / "ramp.h5"
    cli("critical-speed", "ramp", scenes / HUNTING, "--speed-initial", "45", "--speed-final", "35",
        "--deceleration", "5", "-o", out, "--no-plots")
    r = ferrodyn.analysis.critical_speed_ramp(ferrodyn.Scene(scenes / HUNTING), speed_initial=45.0,
                                              speed_final=35.0, deceleration=5.0)
    f = ferrodyn.read(out)
    for key in ("time", "speed", "signal", "envelope"):
        assert same_bits(r[key], f["/ramp/" + key]), key


def test_bifurcation_matches_the_program(scenes, tmp_path):
    out = tmp_path / "bif.h5"
    cli("critical-speed", "bifurcation", scenes / HUNTING, "--speed-max", "45", "--speed-min",
        "38", "--step", "3", "--bracket", "1", *SETTLE_ARGS, "-o", out, "--no-plots")
    r = ferrodyn.analysis.critical_speed_bifurcation(
        ferrodyn.Scene(scenes / HUNTING), speed_max=45.0, speed_min=38.0, step=3.0, bracket=1.0,
        **SETTLE)
    f = ferrodyn.read(out)
    assert same_bits(r["speed"], f["/branch/speed"])
    assert same_bits(r["amplitude"], f["/branch/amplitude"])
    assert r["hopf_speed"] == f.attributes["/branch"]["hopf_speed"]


def test_kij_study_matches_the_program(scenes, tmp_path):
    out = tmp_path / "kij.h5"
    cli("kij-study", scenes / HUNTING, "--k", "1,0.8", "--speed-max", "45", "--speed-min", "38",
        "--step", "3", "--bracket", "1", *SETTLE_ARGS, "-j", "2", "-o", out, "--no-plots")
    r = ferrodyn.analysis.kij_study(ferrodyn.Scene(scenes / HUNTING), k=[1.0, 0.8], speed_max=45.0,
                                    speed_min=38.0, step=3.0, bracket=1.0, jobs=2, **SETTLE)
    f = ferrodyn.read(out)
    assert same_bits(r["k11"], f["/kij/k11"])
    assert same_bits(r["lowest_sustained"], f["/kij/critical_speed"])
    assert same_bits(r["hopf_speed"], f["/kij/hopf_speed"])


def test_sweep_on_threads_matches_the_program(scenes, tmp_path):
    out = tmp_path / "sweep.h5"
    cli("sweep", scenes / HUNTING, "--speed-min", "30", "--speed-max", "48", "--points", "4",
        "--k", "1,0.8", *SETTLE_ARGS, "-o", out, "--no-plots", "-q")
    r = ferrodyn.analysis.sweep(ferrodyn.Scene(scenes / HUNTING), speed_min=30.0, speed_max=48.0,
                                points=4, k=[1.0, 0.8], jobs=2, **SETTLE)
    f = ferrodyn.read(out)
    assert r["complete"] and len(r["speed"]) == 8
    assert same_bits(r["speed"], f["/sweep/speed"])
    assert same_bits(r["amplitude"], f["/sweep/amplitude"])
    assert same_bits(r["period"], f["/sweep/period"])
    assert r["outcome"][-1] == "diverged"


def test_sweep_output_follows_the_output_contract(scenes, tmp_path):
    # As `ferrodyn sweep`: the output holds the sweep once complete (no temporary file left), an
    # existing file is refused without overwrite and kept intact, and an input is never written.
    s = ferrodyn.Scene(scenes / HUNTING)
    request = dict(speed_min=30.0, speed_max=40.0, points=2, jobs=1, **SETTLE)
    out = tmp_path / "sweep.h5"
    r = ferrodyn.analysis.sweep(s, output=out, **request)
    assert r["complete"]
    assert same_bits(r["speed"], ferrodyn.read(out)["/sweep/speed"])
    assert not list(tmp_path.glob("*.part"))
    before = out.read_bytes()
    with pytest.raises(ValueError, match="exists"):
        ferrodyn.analysis.sweep(s, output=out, **request)
    assert out.read_bytes() == before
    r = ferrodyn.analysis.sweep(s, output=out, overwrite=True, **request)
    assert same_bits(r["speed"], ferrodyn.read(out)["/sweep/speed"])
    scene_copy = tmp_path / HUNTING
    scene_copy.write_bytes((scenes / HUNTING).read_bytes())
    with pytest.raises(ValueError, match="input"):
        ferrodyn.analysis.sweep(ferrodyn.Scene(scene_copy), output=scene_copy, overwrite=True,
                                **request)
    assert scene_copy.read_bytes() == (scenes / HUNTING).read_bytes()


def test_assessment_matches_the_program(scenes, tmp_path):
    run = tmp_path / "curve.h5"
    cli("run", scenes / "manchester_curve_1200.yaml", "--t-end", "1", "-o", run, "--no-plots",
        "-q", cwd=SOURCE)
    out = tmp_path / "assessment.h5"
    printed = cli("assess", run, "--section-length", "20", "--mu", "0.3", "-o", out,
                  "--no-plots").stdout
    r = ferrodyn.analysis.assess(str(run), section_length=20.0, mu=0.3)
    f = ferrodyn.read(out)
    assert len(r["rows"]["value"]) > 0
    for column in ("value", "limit", "max_abs", "position", "p_low", "p_median", "p_high", "rms"):
        assert same_bits(r["rows"][column], f["/assessment/rows/" + column]), column
    verdict = np.array([{"pass": 1.0, "fail": 0.0}.get(v, np.nan) for v in r["rows"]["verdict"]])
    assert same_bits(verdict, f["/assessment/rows/verdict"])
    assert same_bits(r["sections"]["start"], f["/assessment/sections/start"])
    for k, sig in enumerate(r["signals"]):
        g = f"/assessment/signals/{k:03d}"
        assert f.attributes[g]["quantity"] == sig["quantity"]
        assert f.attributes[g]["item"] == sig["item"]
        assert same_bits(sig["value"], f[g + "/value"])
        assert same_bits(sig["position"], f[g + "/position"])
    assert r["mu"] == f.attrs["mu"] == 0.3
    assert (f.attrs["pass"] == "yes") == r["pass"]
    assert printed.startswith(r["summary"])
    with pytest.raises(ValueError, match="category"):
        ferrodyn.analysis.assess(str(run), category="tram")
    with pytest.raises(ValueError, match="twist_test and no_twist_test"):
        ferrodyn.analysis.assess(str(run), twist_test=True, no_twist_test=True)
    for angle in (0.0, -10.0, 90.0):  # Nadal's limit needs a flange angle in (0, 90) deg
        with pytest.raises(ValueError, match="flange_angle_deg: allowed"):
            ferrodyn.analysis.assess(str(run), flange_angle_deg=angle)


def test_bad_request_names_the_keyword(scenes):
    s = ferrodyn.Scene(scenes / HUNTING)
    with pytest.raises(ValueError, match="speed_min/speed_max"):
        ferrodyn.analysis.sweep(s, speed_min=30.0, speed_max=20.0)
    with pytest.raises(TypeError, match="allowed"):
        ferrodyn.analysis.sweep(s, speed_minimum=30.0)
    with pytest.raises(ValueError, match="coefficient"):
        ferrodyn.analysis.kij_study(s, coefficient="k33", speed_max=45.0, speed_min=38.0)
