"""Exercise I: what a submission cannot plant.  The installation check's messages (a package missing or too old,
MuJoCo broken in the sandbox), and the refusal of unsafe MJCF before MuJoCo reads it."""

import numpy as np
import pytest

from checks import problem_01
from grader.checking import CheckFailure
import probes
from probes import _mjcf
from reference import problem_02

mujoco = pytest.importorskip("mujoco")


class FakeContext:
    """Answers the probes of problem 1 with canned results, by the probe's name (as the context's doors name it)."""

    def __init__(self, student, reference=None):
        self._student, self._reference = student, reference

    def student(self, probe, *args, timeout=None):
        return self._student[probes.name_of(probe)]

    def reference(self, probe, *args, persist=False):
        return self._reference[probes.name_of(probe)]


def _environment(**packages):
    entries = {name: {"version": "9.9.9", "distribution": "9.9.9", "error": None} for name in problem_01.PACKAGES}
    entries.update(packages)
    found = {"python": "3.11.7", "packages": entries}
    return {"problem_01.environment": {**found, "student": {"python": "3.11.7", **{n: "9.9.9" for n in entries}}}}


def test_a_missing_package_is_listed_with_the_command_that_installs_it():
    missing = {"version": None, "distribution": None, "error": "ModuleNotFoundError: No module named 'mujoco'"}
    with pytest.raises(CheckFailure) as failure:
        problem_01.check_versions(FakeContext(_environment(mujoco=missing)))
    assert failure.value.diagnosis == "install"
    assert "pip install mujoco" in failure.value.message and "does not import" in failure.value.message


def test_an_old_package_is_listed_with_the_upgrade_command():
    old = {"version": "1.21.0", "distribution": "1.21.0", "error": None}
    with pytest.raises(CheckFailure) as failure:
        problem_01.check_versions(FakeContext(_environment(numpy=old)))
    assert failure.value.diagnosis == "install"
    assert 'pip install --upgrade "numpy>=1.26"' in failure.value.message


def test_version_strings_compare_by_their_numbers():
    assert problem_01._release("1.26.4") == (1, 26, 4) >= (1, 26)
    assert problem_01._release("3.3.0rc1") == (3, 3, 0) and problem_01._release("2.0.dev0") == (2, 0)
    assert problem_01._release(None) == () < (1,)


def test_mujoco_broken_in_the_sandbox_fails_the_tiny_model():
    refused = {"error": "MuJoCo does not import here (libmujoco.so: cannot open shared object file)"}
    with pytest.raises(CheckFailure) as failure:
        problem_01.check_mujoco_runs(FakeContext({"problem_01.tiny_model": refused}))
    assert "does not import" in failure.value.message


# --- unsafe MJCF is refused before MuJoCo sees it ----------------------------------------------------------------

SAFE = problem_02.pendulum(950.0, 9.81)


@pytest.mark.parametrize("xml, reason", [
    ('<mujoco><include file="/etc/passwd"/></mujoco>', "<include>"),
    ('<mujoco><asset><mesh name="m" file="link.stl"/></asset></mujoco>', "<mesh>"),
    ('<mujoco><asset><texture name="t" builtin="checker" width="100000" height="100000"/></asset></mujoco>',
     "<texture>"),
    ('<mujoco><compiler meshdir="/root"/></mujoco>', "names a file or directory"),
    ('<mujoco><asset><material name="m" file="x"/></asset></mujoco>', "names a file or directory"),
    ('<mujoco><worldbody><replicate count="100000"><body/></replicate></worldbody></mujoco>', "<replicate>"),
    ('<mujoco><size memory="100G"/></mujoco>', "<size>"),
    ('<mujoco><extension><plugin plugin="mujoco.elasticity.solid"/></extension></mujoco>', "<extension>"),
    ('<?xml version="1.0"?><!DOCTYPE m [<!ENTITY a "aaaa">]><mujoco>&a;</mujoco>', "DOCTYPE"),
    ("<mujoco><worldbody>", "not well-formed"),
    ("<robot/>", "root element"),
    ("x" * (_mjcf.MAX_CHARS + 1), "characters"),
    ("<mujoco>" + "<worldbody/>" * (_mjcf.MAX_ELEMENTS + 1) + "</mujoco>", "XML elements"),
    (None, "as a str"),
], ids=["include", "mesh", "texture", "meshdir", "file-attribute", "replicate", "size", "plugin", "entities",
        "malformed", "not-mjcf", "long", "many-elements", "not-text"])
def test_unsafe_or_huge_models_are_refused(xml, reason):
    with pytest.raises(_mjcf.ModelRefused, match=reason):
        _mjcf.refuse_unsafe(xml)


def test_mujoco_reads_files_named_in_a_string_model_which_is_why_they_are_refused(tmp_path):
    (tmp_path / "part.xml").write_text('<mujoco><worldbody><geom size="0.1"/></worldbody></mujoco>')
    model = mujoco.MjModel.from_xml_string(f'<mujoco><include file="{tmp_path / "part.xml"}"/></mujoco>', {})
    assert model.ngeom == 1  # an empty assets dictionary does not stop it


def test_a_course_model_passes_and_its_runs_are_bounded():
    model, data = _mjcf.load(SAFE)
    with pytest.raises(_mjcf.ModelRefused, match="steps"):
        _mjcf.run(model, data, 10.0 * _mjcf.MAX_STEPS, 0.01)
    tiny = SAFE.replace('timestep="0.001"', 'timestep="1e-07"')
    with pytest.raises(_mjcf.ModelRefused, match="at most"):
        _mjcf.run(*_mjcf.load(tiny), 10.0, 0.01)


def test_a_diverging_run_stops_with_the_time_and_mujocos_warning():
    wild = SAFE.replace('damping="0.0"', 'damping="1e6"')
    run = _mjcf.run(*_mjcf.load(wild), 10.0, 0.01)
    assert run["diverged"]["time"] < 0.1 and "qvel" in run["diverged"]["reason"].lower()
    assert np.isnan(run["qpos"][-1]).all()


def test_too_many_bodies_are_refused_after_loading():
    bodies = "".join(f'<body pos="{i} 0 0"><joint/><geom size="0.1"/></body>' for i in range(_mjcf.MAX_BODIES + 1))
    with pytest.raises(_mjcf.ModelRefused, match="bodies"):
        _mjcf.load(f"<mujoco><worldbody>{bodies}</worldbody></mujoco>")
