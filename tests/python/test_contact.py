"""The contact layer from Python: every tangential model on arrays of cases gives the program's
`contact eval --batch` numbers to the last bit; normal models against Hertz's closed form and the
program's semi-Hertz patches; profiles, the contact-point search and the contact table against
the program's geometry verbs."""
import csv
import io
import json
import math

import numpy as np
import pytest

import ferrodyn
from conftest import SOURCE, cli, same_bits

PROFILES = SOURCE / "data" / "profiles"
WHEEL, RAIL = PROFILES / "MBench_S1002_v3.prw", PROFILES / "MBench_UIC60_v3.prr"
# Options keeping the numerical models quick on a test's few cases.
QUICK = {"mim": {"elements": "12"}}


def cases(n=12, seed=7):
    """Hertzian cases across micro-slip to full slip, with spin (seeded)."""
    rng = np.random.default_rng(seed)
    return {"a": rng.uniform(4e-3, 8e-3, n), "b": rng.uniform(3e-3, 7e-3, n),
            "fn": rng.uniform(4e4, 1e5, n), "mu": np.full(n, 0.3),
            "xi_x": rng.uniform(-3e-3, 3e-3, n), "xi_y": rng.uniform(-3e-3, 3e-3, n),
            "spin": rng.uniform(-0.5, 0.5, n)}


def program_batch(model, c, options, tmp_path):
    """`ferrodyn contact eval --model M --batch` on the cases; its columns as float arrays."""
    keys = list(c)
    text = ",".join(keys) + "\n" + "".join(
        ",".join(repr(float(c[k][i])) for k in keys) + "\n" for i in range(len(c["a"])))
    args = ["contact", "eval", "--model", model, "--batch"]
    for k, v in options.items():
        args += ["--option", f"{k}={v}"]
    import subprocess
    from conftest import EXE
    p = subprocess.run([EXE, *args], input=text, capture_output=True, text=True, check=True)
    rows = list(csv.DictReader(io.StringIO(p.stdout)))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0] if k not in ("row", "model")}


@pytest.fixture(scope="module")
def mim_table(tmp_path_factory):
    path = tmp_path_factory.mktemp("table") / "mim_table.h5"
    cli("contact", "mim-table", "-o", path, "--elements", "8", "--grid", "minor", "--threads", "2")
    return path


@pytest.mark.parametrize("model", ferrodyn.contact.tangential_models())
def test_every_tangential_model_matches_the_program_bitwise(model, tmp_path, request):
    options = dict(QUICK.get(model, {}))
    if model == "mim_table":
        options["table"] = str(request.getfixturevalue("mim_table"))
    c = cases()
    r = ferrodyn.contact.tangential(model, options=options, **c)
    ref = program_batch(model, c, options, tmp_path)
    for key in ("semi_axis_x", "semi_axis_y", "peak_pressure", "force_x", "force_y", "moment_z",
                "adhesion_fraction"):
        assert same_bits(r[key], ref[key]), key


def test_mim_table_from_the_environment_as_the_program(mim_table, scenes, tmp_path, monkeypatch):
    """$FERRO_MIM_TABLE gives mim_table its table when none is named, from Python as in the
    program: the same forces as the table given by option, the same run as `ferrodyn run
    --tangential mim_table` under the same environment."""
    monkeypatch.setenv("FERRO_MIM_TABLE", str(mim_table))
    c = cases()
    by_env = ferrodyn.contact.tangential("mim_table", **c)
    by_option = ferrodyn.contact.tangential("mim_table", options={"table": str(mim_table)}, **c)
    assert same_bits(by_env["force_y"], by_option["force_y"])
    scene = scenes / "cooperrider_straight.yaml"
    out = tmp_path / "cli.h5"
    cli("run", scene, "--tangential", "mim_table", "--t-end", "0.2", "-o", out, "--no-plots", "-q")
    r = ferrodyn.run(ferrodyn.Scene(scene), tangential="mim_table", t_end=0.2)
    ref = ferrodyn.read(out)
    assert r.metadata["tangential_model"] == "mim_table"
    for name in ("wheelset_1.y", "wheelset_1.left.Y"):
        assert same_bits(r[name], ref.signals[name]), name
    monkeypatch.delenv("FERRO_MIM_TABLE")
    with pytest.raises(ferrodyn.SceneError, match="table"):
        ferrodyn.run(ferrodyn.Scene(scene), tangential="mim_table", t_end=0.2)


def test_arrays_broadcast_and_scalars():
    xi = np.linspace(0.0, 5e-3, 50)
    r = ferrodyn.contact.tangential("fastsim", a=6e-3, b=5e-3, fn=8e4, mu=0.3, xi_y=xi)
    assert r["force_y"].shape == (50,) and r["force_y"][0] == 0.0
    # Saturation: Coulomb bounds the force; the force opposes the creepage (on the wheel).
    assert (np.abs(r["force_y"]) <= 0.3 * 8e4 * (1 + 1e-12)).all() and r["force_y"][-1] < 0
    with pytest.raises(ValueError, match="case 2"):
        ferrodyn.contact.tangential("fastsim", a=6e-3, b=5e-3, fn=np.array([8e4, 8e4, -1.0]),
                                    mu=0.3)


def test_hertz_normal_against_closed_form():
    """Two steel spheres: a = (3 F R / (4 E*))^(1/3), p0 = 3 F / (2 pi a^2) (Hertz 1882)."""
    g, nu = 82e9, 0.28
    e_star = 2 * g * (1 + nu) / (2 * (1 - nu**2))
    fn = np.array([1e4, 5e4, 1e5])
    curvature = 1 / (2 * 0.5)  # A = B = 1 / (2 R) for a sphere of radius R = 0.5 m on a plane
    r = ferrodyn.contact.normal("hertz", fn=fn, curvature_x=curvature, curvature_y=curvature,
                                g1=g, nu1=nu, g2=g, nu2=nu)
    a = (3 * fn * 0.5 / (4 * e_star)) ** (1 / 3)
    np.testing.assert_allclose(r["semi_axis_x"], a, rtol=1e-6)  # elliptic integrals to 1e-6
    np.testing.assert_allclose(r["semi_axis_y"], a, rtol=1e-6)
    np.testing.assert_allclose(r["peak_pressure"], 3 * fn / (2 * math.pi * a**2), rtol=1e-5)
    assert list(r["patch_case"]) == [0, 1, 2]


def test_semi_hertz_matches_the_program_patches(tmp_path):
    """The two-lobe case of scenarios/cases/contact: the program's patch summary (JSON)."""
    case = SOURCE / "scenarios" / "cases" / "contact" / "semi_hertz_two_lobes.yaml"
    p = cli("contact", "patch", case, "-o", tmp_path, "--no-plots")
    patches = json.loads(p.stdout[: p.stdout.rindex("]") + 1])
    y = np.linspace(-0.03, 0.03, 2401)
    z = np.minimum(1.6667 * (y + 0.006) ** 2, 12.5 * (y - 0.010) ** 2 + 5.0e-6)
    g = 210e9 / (2 * 1.28)
    r = ferrodyn.contact.normal("semi_hertz", options={"strips": 120}, fn=73575.0,
                                curvature_x=1.08149, g1=g, nu1=0.28, g2=g, nu2=0.28, gap_y=y,
                                gap_z=z)
    assert len(r["semi_axis_x"]) == len(patches) == 2
    for k, q in enumerate(patches):
        for key in ("y_center", "semi_axis_x", "semi_axis_y", "normal_force", "peak_pressure"):
            assert r[key][k] == pytest.approx(q[key], rel=1e-12), key


def test_profile_and_point_search_match_the_program():
    wheel = ferrodyn.contact.read_profile(WHEEL, "wheel")
    assert wheel["kind"] == "wheel" and (np.diff(wheel["y"]) > 0).all()
    pair = ferrodyn.contact.WheelRailPair(str(WHEEL), str(RAIL))
    r = pair.search(y=0.004, yaw=0.002, load=160000.0)
    ref = json.loads(cli("geometry", "search", "--wheel", WHEEL, "--rail", RAIL, "--y", "0.004",
                         "--yaw", "0.002", "--load", "160000").stdout)
    assert r["vertical"] * 1e3 == ref["pose"]["height_mm"] and r["roll"] == ref["pose"]["roll_rad"]
    assert len(r["side"]) == len(ref["points"])
    for k, q in enumerate(ref["points"]):
        assert r["side"][k] == q["side"]
        assert r["lead"][k] * 1e3 == q["lead_mm"]
        assert r["contact_angle"][k] * 180.0 / math.pi == q["contact_angle_deg"]
        assert r["normal_force"][k] == q["normal_force_n"]
    # Vertical balance: the contact loads carry the wheelset's load.
    assert sum(r["normal_force"] * np.cos(r["contact_angle"])) == pytest.approx(160000.0, rel=2e-3)


def test_contact_table_matches_geometry_pair(tmp_path):
    pair_file = SOURCE / "data" / "manchester_contact_benchmark_a22.yaml"
    cli("geometry", "pair", pair_file, "-o", tmp_path, "--no-plots")
    ref = ferrodyn.read(tmp_path / "contact_table.h5")
    t = ferrodyn.contact.WheelRailPair.from_pair_file(str(pair_file)).table()
    assert same_bits(t["lateral"], ref["/lateral"])
    assert same_bits(t["delta_r"], ref["/delta_r"].ravel())
    lam = ferrodyn.contact.WheelRailPair.equivalent_conicity(t["lateral"], t["delta_r"], 3e-3)
    assert 0.0 < lam < 1.0
