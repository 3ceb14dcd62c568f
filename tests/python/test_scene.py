"""Scenes from Python: the file's values, values changed by key (through included files), text
scenes, and bad input raised as SceneError with its file, line and key."""
import pytest

import ferrodyn
from conftest import cli

BAD_SPEED = """schema_version: 1
name: bad_speed
model:
  type: suspended_wheelset
  mass: 1887
  yaw_inertia: 1000
  half_gauge: 0.7465
  rolling_radius: 0.46
  conicity: 0.15
  primary_stiffness_x: 4.0e6
  primary_stiffness_y: 4.0e6
track: {type: straight}
contact: {semi_axis_a: 6.0e-3, semi_axis_b: 5.0e-3}
simulation:
  speed: -3.0
  t_end: 1.0
solver: {integrator: cvode_bdf}
output: {file: out/bad.h5}
"""


def test_scene_file_values(scenes):
    s = ferrodyn.Scene(scenes / "wheelset_hunting.yaml")
    assert s.name == "wheelset_hunting"
    assert s.model_type == "suspended_wheelset"
    assert s["simulation.speed"] == s.speed
    assert s["solver.integrator"] == s.integrator
    assert s["no.such.key"] is None


def test_any_key_through_included_files(scenes):
    s = ferrodyn.Scene(scenes / "manchester_straight_erri.yaml")
    # The vehicle is a file the scene names: its values are reached through it.
    assert s["model.vehicle.wheel_rail.friction"] == 0.32
    s.update({"simulation.speed_kmh": 144.0, "solver.integrator": "arkode_erk",
              "contact.tangential": "fastsim", "model.vehicle.car_body.mass": 30000.0,
              "track.length": 700.0})
    assert s.speed == pytest.approx(40.0, rel=1e-15) and s.integrator == "arkode_erk"
    assert s["model.vehicle.car_body.mass"] == 30000.0
    assert s.overrides["track.length"] == 700.0
    del s["simulation.speed_kmh"]
    assert s.speed == pytest.approx(200.0 / 3.6, rel=1e-15)  # the scene's own 200 km/h


def test_override_matches_the_program_option(scenes):
    """A value set by key gives the same scene as the program's option (--speed)."""
    s = ferrodyn.Scene(scenes / "wheelset_hunting.yaml", overrides={"simulation.speed": 41.5})
    by_kwarg = ferrodyn.run(ferrodyn.Scene(scenes / "wheelset_hunting.yaml"), speed=41.5, t_end=1.0)
    by_key = ferrodyn.run(s, t_end=1.0)
    assert (by_key["wheelset.y"] == by_kwarg["wheelset.y"]).all()


def test_yaml_text_scene(scenes):
    text = (scenes / "wheelset_hunting.yaml").read_text()
    s = ferrodyn.Scene.from_yaml(text, path=scenes / "inline.yaml")
    assert s.speed == ferrodyn.Scene(scenes / "wheelset_hunting.yaml").speed


def test_bad_file_value_located(tmp_path):
    f = tmp_path / "bad_speed.yaml"
    f.write_text(BAD_SPEED)
    with pytest.raises(ferrodyn.SceneError) as e:
        ferrodyn.Scene(f)
    assert e.value.file == str(f)
    assert e.value.line == 15
    assert e.value.key == "simulation.speed"
    assert "must be > 0" in e.value.message
    assert isinstance(e.value, ValueError)
    # The program reports the same location.
    p = cli("validate", f, check=False)
    assert p.returncode == 2 and f"{f}:15:" in p.stderr and "simulation.speed" in p.stderr


def test_bad_text_scene_located():
    with pytest.raises(ferrodyn.SceneError) as e:
        ferrodyn.Scene.from_yaml(BAD_SPEED, path="inline.yaml")
    assert (e.value.file, e.value.line, e.value.key) == ("inline.yaml", 15, "simulation.speed")


def test_bad_override_named_and_rejected(scenes):
    s = ferrodyn.Scene(scenes / "wheelset_hunting.yaml")
    with pytest.raises(ferrodyn.SceneError) as e:
        s["simulation.speed"] = -1.0
    assert e.value.key == "simulation.speed" and e.value.line is None
    assert "override" in str(e.value)
    assert s.speed == 36.98 and s.overrides == {}  # the scene is as it was
    with pytest.raises(ferrodyn.SceneError) as e:
        s["simulation.sped"] = 40.0  # misspelt: the nearest key is suggested
    assert "speed" in e.value.message
    with pytest.raises(ferrodyn.SceneError) as e:
        s["solver.integrator"] = "euler"
    assert e.value.key == "solver.integrator" and "cvode_bdf" in e.value.message


def test_bad_run_argument_named(scenes):
    s = ferrodyn.Scene(scenes / "wheelset_hunting.yaml")
    with pytest.raises(ferrodyn.SceneError) as e:
        ferrodyn.run(s, t_end=-1.0)
    assert e.value.key == "t_end" and e.value.file == s.path
    with pytest.raises(TypeError):
        ferrodyn.run(s, t_ende=1.0)  # unknown keyword: the allowed ones are listed


def test_validate_builds_the_model(scenes, tmp_path):
    text = (scenes / "manchester_straight_erri.yaml").read_text()
    s = ferrodyn.Scene.from_yaml(text, path=scenes / "x.yaml",
                                 overrides={"simulation.initial": {"no_such_state": 0.001}})
    with pytest.raises(ferrodyn.SceneError) as e:
        s.validate()
    assert e.value.key.startswith("simulation.initial") and e.value.line is None
    assert "no_such_state" in str(e.value)
