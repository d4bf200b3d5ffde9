"""Loading, describing and running MJCF models (problems 1-5): shared by the probes of Exercise I.

A student's MJCF is untrusted input to a C library, read only here, inside the sandbox.  Before MuJoCo sees it the
text is checked: a size cap, well-formed XML without a DOCTYPE or entities, only the elements a course model needs
(no ``<include>``, no meshes, textures, height fields, plugins or generated bodies), no attribute that names a file
or a directory (MuJoCo reads files named in a string model from the disk, assets dictionary or not), and caps on
the number of elements.  After loading, caps on bodies, joints and the number of simulation steps; a run that
produces NaN or makes MuJoCo warn (it silently resets a diverging simulation) stops with the time and the warning.

Every function returns plain data; a model that is refused or does not load comes back as ``{"error": message}``.
"""

import math
import re
import xml.etree.ElementTree as ElementTree

from ._forms import Arr, Dict, Either, Flag, Maybe, Num, Seq, Text

__all__ = [
    "REFUSED",
    "DESCRIPTION",
    "RUN",
    "RESULT_OF_DESCRIBE",
    "RESULT_OF_RUN",
    "MAX_CHARS",
    "MAX_ELEMENTS",
    "MAX_BODIES",
    "MAX_STEPS",
    "ModelRefused",
    "refuse_unsafe",
    "load",
    "describe",
    "run",
    "tangent_acceleration",
    "guarded",
    "posed",
]

MAX_CHARS = 100_000

#: a model refused or not loaded: ``{"error": message}``
REFUSED = Dict({"error": Text()})
#: ``describe(model, data)``
DESCRIPTION = Dict({
    "gravity": Arr(3), "timestep": Num(), "integrator": Text(), "keyframes": Num(), "contacts": Num(),
    "qpos": Arr(None), "qvel": Arr(None),
    "bodies": Seq(Dict({"name": Text(), "parent": Num(), "mass": Num(), "com": Arr(3), "inertia": Arr(3, 3),
                        "frame": Arr(3, 3)}, optional=("frame",))),
    "joints": Seq(Dict({"name": Text(), "type": Text(), "body": Num(), "anchor": Arr(3), "axis": Arr(3),
                        "damping": Num(), "armature": Num(), "frictionloss": Num(), "stiffness": Num()})),
    "actuators": Seq(Dict({"name": Text(), "joint": Num(), "gear": Num(), "unit_torque": Arr(None),
                           "stateful": Flag()})),
    "equalities": Seq(Dict({"type": Text(), "active": Flag(), "point1": Arr(3), "point2": Arr(3),
                            "to_world": Flag()}, optional=("point1", "point2", "to_world"))),
    "sites": Seq(Dict({"name": Text(), "body": Num(), "pos": Arr(3), "world": Arr(3)})),
}, optional=("sites",))
#: ``run(model, data, ...)``: after a divergence the samples stay NaN
RUN = Dict({"t": Arr(None), "qpos": Arr(None, None, finite=False), "qvel": Arr(None, None, finite=False),
            "steps": Num(), "timestep": Num(), "integrator": Text(), "max_contacts": Num(),
            "diverged": Maybe(Dict({"time": Num(), "reason": Text()}))})
#: what a probe that describes (runs) a student's model replies: the model, or why it was not used
RESULT_OF_DESCRIBE = Either(REFUSED, DESCRIPTION)
RESULT_OF_RUN = Either(REFUSED, RUN)
MAX_ELEMENTS = 1_000
MAX_BODIES = 20
MAX_DOFS = 30
MAX_STEPS = 200_000

#: the elements a course model may use (MJCF's modelling elements without file access or generated structure)
ALLOWED = frozenset("""
    mujoco compiler option flag visual global quality headlight map scale rgba statistic default
    worldbody body frame inertial joint freejoint geom site camera light
    equality connect weld tendon fixed spatial
    actuator motor position velocity intvelocity damper general
    sensor jointpos jointvel jointactuatorfrc actuatorpos actuatorvel actuatorfrc framepos framequat framelinvel
    frameangvel framelinacc frameangacc subtreecom subtreelinvel clock
    keyframe key contact exclude pair asset material
""".split())
#: attributes that name files or directories of files
_FILE_ATTRIBUTE = re.compile(r"(file|dir)$", re.IGNORECASE)
_DECLARATIONS = re.compile(r"<!\s*(DOCTYPE|ENTITY|ELEMENT|ATTLIST)", re.IGNORECASE)


class ModelRefused(Exception):
    """The model text is refused before MuJoCo reads it, or MuJoCo cannot load it."""


def refuse_unsafe(xml) -> None:
    """Raise ``ModelRefused`` unless ``xml`` is MJCF text that is safe to hand to MuJoCo."""
    if not isinstance(xml, str):
        raise ModelRefused(f"the function must return the MJCF text as a str, got {type(xml).__name__}")
    if len(xml) > MAX_CHARS:
        raise ModelRefused(f"the model text has {len(xml)} characters; a course model needs far fewer "
                           f"(at most {MAX_CHARS} are read)")
    if _DECLARATIONS.search(xml):
        raise ModelRefused("the model text contains a DOCTYPE or entity declaration, which MJCF does not use")
    try:
        root = ElementTree.fromstring(xml)
    except ElementTree.ParseError as exc:
        raise ModelRefused(f"the model text is not well-formed XML: {exc}") from None
    if root.tag != "mujoco":
        raise ModelRefused(f"the root element of an MJCF model is <mujoco>, not <{root.tag}>")
    count = 0
    for element in root.iter():
        count += 1
        if count > MAX_ELEMENTS:
            raise ModelRefused(f"the model has more than {MAX_ELEMENTS} XML elements; a course model needs far fewer")
        if not isinstance(element.tag, str) or element.tag not in ALLOWED:
            raise ModelRefused(
                f"the element <{element.tag}> is not accepted in a course model: the grader refuses <include>, "
                "meshes, textures, height fields, plugins and generated bodies (a model may not read files)")
        for name in element.attrib:
            if _FILE_ATTRIBUTE.search(name):
                raise ModelRefused(f'the attribute {name}="..." of <{element.tag}> names a file or directory; a '
                                   "course model may not read files")


def load(xml):
    """``(model, data)`` of the checked text, reset to its first keyframe (if any) and forwarded."""
    refuse_unsafe(xml)
    try:
        import mujoco
    except ImportError as exc:
        raise ModelRefused(f"MuJoCo does not import here ({exc}): install it with `pip install mujoco` "
                           "(grade problem-1 checks the installation)") from None
    _quiet(mujoco)
    try:
        model = mujoco.MjModel.from_xml_string(xml)
    except Exception as exc:  # noqa: BLE001 - MuJoCo's compile errors are the student's: report them
        raise ModelRefused(f"MuJoCo cannot load the model: {str(exc).strip()[:1500]}") from None
    if model.nbody - 1 > MAX_BODIES or model.nv > MAX_DOFS:
        raise ModelRefused(f"the model has {model.nbody - 1} bodies and {model.nv} degrees of freedom; a course "
                           f"model has at most {MAX_BODIES} and {MAX_DOFS}")
    data = mujoco.MjData(model)
    if model.nkey:
        mujoco.mj_resetDataKeyframe(model, data, 0)
    mujoco.mj_forward(model, data)
    return model, data


#: MuJoCo's warnings of this process (it would otherwise print them and append them to MUJOCO_LOG.TXT)
WARNINGS: list = []


def _quiet(mujoco) -> None:
    """Collect MuJoCo's warnings in ``WARNINGS`` instead of letting it write a log file into the working directory."""
    if hasattr(mujoco, "set_mju_user_warning"):
        mujoco.set_mju_user_warning(lambda text: WARNINGS.append(str(text)[:300]) if len(WARNINGS) < 20 else None)


def guarded(build):
    """The result of ``build()``, or ``{"error": message}`` when the model is refused or does not load."""
    try:
        return build()
    except ModelRefused as exc:
        return {"error": str(exc)}


def _name(model, kind, index):
    import mujoco

    return mujoco.mj_id2name(model, kind, index) or ""


def _integrator(model):
    import mujoco

    try:
        return mujoco.mjtIntegrator(int(model.opt.integrator)).name.removeprefix("mjINT_").lower()
    except ValueError:
        return str(int(model.opt.integrator))


def integrated_as_sheet(model, data):
    """``(model, data)`` with the sheet's integration (RK4 at 1 ms) in place of the model's own: the same model
    stepped as the sheet's, to tell a slip of its integration from one of the model."""
    import mujoco

    model.opt.timestep = 0.001
    model.opt.integrator = mujoco.mjtIntegrator.mjINT_RK4
    mujoco.mj_forward(model, data)
    return model, data


def _equality_points(model, data, i):
    """World positions of the two points a ``connect`` constraint joins (bodies with anchors, or sites)."""
    import mujoco
    import numpy as np

    objtype = int(model.eq_objtype[i]) if hasattr(model, "eq_objtype") else int(mujoco.mjtObj.mjOBJ_BODY)
    a, b = int(model.eq_obj1id[i]), int(model.eq_obj2id[i])
    if objtype == int(mujoco.mjtObj.mjOBJ_SITE):
        return data.site_xpos[a].copy(), data.site_xpos[b].copy(), -1 if b < 0 else int(model.site_bodyid[b])
    anchor1, anchor2 = np.asarray(model.eq_data[i][0:3]), np.asarray(model.eq_data[i][3:6])
    p1 = data.xpos[a] + data.xmat[a].reshape(3, 3) @ anchor1
    p2 = data.xpos[b] + data.xmat[b].reshape(3, 3) @ anchor2
    return p1, p2, b


def posed(model, data, qpos=None):
    """``(model, data)`` with the joints at ``qpos`` (when it has the model's ``nq`` entries), positions computed."""
    import mujoco
    import numpy as np

    if qpos is not None and len(qpos) == model.nq:
        data.qpos[:] = np.asarray(qpos, dtype=float)
        mujoco.mj_forward(model, data)
    return model, data


def describe(model, data) -> dict:
    """What the model declares, in the world frame of its initial configuration: gravity, integrator, the moving
    bodies (mass, centre of mass, inertia about it, orientation), the joints (type, anchor, axis, damping), the
    actuators (the joint torque at unit control), the equality constraints, the sites (their body, their position in
    it and in the world), keyframes and contacts."""
    import mujoco
    import numpy as np

    bodies = []
    for b in range(1, model.nbody):
        R = data.ximat[b].reshape(3, 3)
        bodies.append({
            "name": _name(model, mujoco.mjtObj.mjOBJ_BODY, b),
            "parent": int(model.body_parentid[b]),
            "mass": float(model.body_mass[b]),
            "com": data.xipos[b].copy(),
            "inertia": R @ np.diag(model.body_inertia[b]) @ R.T,
            "frame": data.xmat[b].reshape(3, 3).copy(),
        })
    types = _enum_names(mujoco.mjtJoint, "mjJNT_")
    joints = []
    for j in range(model.njnt):
        dof = int(model.jnt_dofadr[j])
        joints.append({
            "name": _name(model, mujoco.mjtObj.mjOBJ_JOINT, j),
            "type": types.get(int(model.jnt_type[j]), "?"),
            "body": int(model.jnt_bodyid[j]),
            "anchor": data.xanchor[j].copy(),
            "axis": data.xaxis[j].copy(),
            "damping": float(model.dof_damping[dof]),
            "armature": float(model.dof_armature[dof]),
            "frictionloss": float(model.dof_frictionloss[dof]),
            "stiffness": float(model.jnt_stiffness[j]),
        })
    actuators = []
    if model.nu:
        saved = data.ctrl.copy()
        for u in range(model.nu):
            data.ctrl[:] = 0.0
            data.ctrl[u] = 1.0
            mujoco.mj_forward(model, data)
            actuators.append({
                "name": _name(model, mujoco.mjtObj.mjOBJ_ACTUATOR, u),
                "joint": int(model.actuator_trnid[u][0]) if int(model.actuator_trntype[u]) == 0 else -1,
                "gear": float(model.actuator_gear[u][0]),
                "unit_torque": data.qfrc_actuator.copy(),
                "stateful": bool(int(model.actuator_dyntype[u]) != 0),
            })
        data.ctrl[:] = saved
        mujoco.mj_forward(model, data)
    equalities = []
    eq_types = _enum_names(mujoco.mjtEq, "mjEQ_")
    for i in range(model.neq):
        kind = eq_types.get(int(model.eq_type[i]), "?")
        entry = {"type": kind, "active": bool(model.eq_active0[i]) if hasattr(model, "eq_active0") else True}
        if kind == "connect":
            p1, p2, other = _equality_points(model, data, i)
            entry.update({"point1": p1, "point2": p2, "to_world": other == 0})
        equalities.append(entry)
    sites = [{"name": _name(model, mujoco.mjtObj.mjOBJ_SITE, k), "body": int(model.site_bodyid[k]),
              "pos": model.site_pos[k].copy(), "world": data.site_xpos[k].copy()} for k in range(model.nsite)]
    return {
        "gravity": model.opt.gravity.copy(),
        "timestep": float(model.opt.timestep),
        "integrator": _integrator(model),
        "bodies": bodies,
        "joints": joints,
        "actuators": actuators,
        "equalities": equalities,
        "sites": sites,
        "keyframes": int(model.nkey),
        "qpos": data.qpos.copy(),
        "qvel": data.qvel.copy(),
        "contacts": int(data.ncon),
    }


def _enum_names(enum, prefix) -> dict:
    """``{value: lower-case name}`` of a MuJoCo enum's members that start with ``prefix``."""
    return {int(getattr(enum, name)): name.removeprefix(prefix).lower() for name in dir(enum)
            if name.startswith(prefix)}


def _warnings(data) -> dict:
    import mujoco

    found = {}
    for value, name in _enum_names(mujoco.mjtWarning, "mjWARN_").items():
        number = int(data.warning[value].number)
        if number:
            found[name] = number
    return found


def run(model, data, duration, sample, control=None) -> dict:
    """Step the model for ``duration`` seconds and return its state at the times ``0, sample, 2 sample, ...``
    (linear interpolation between the steps): ``{"t", "qpos", "qvel", "steps", "timestep", "diverged", ...}``.

    ``control``: ``None`` keeps the controls as loaded (a keyframe's); ``"sine"`` sets every control to ``sin(t)``
    at the middle of each step (the tutorial's sine-wave source).  The run stops early, with ``"diverged"`` set
    to the time and the reason, when the state stops being finite or MuJoCo warns (it resets a diverging
    simulation silently); the samples after that stay NaN.
    """
    import mujoco
    import numpy as np

    dt = float(model.opt.timestep)
    if not dt > 0 or not math.isfinite(dt):
        raise ModelRefused(f"the model's timestep {dt!r} is not a positive number")
    steps = int(math.ceil(duration / dt - 1e-9))
    if steps > MAX_STEPS:
        raise ModelRefused(f"{duration:g} s with a timestep of {dt:g} s are {steps} steps; the grader runs at most "
                           f"{MAX_STEPS} (a timestep of 1 ms is accurate with RK4)")
    times = np.arange(int(round(duration / sample)) + 1) * sample
    qpos = np.full((len(times), model.nq), np.nan)
    qvel = np.full((len(times), model.nv), np.nan)
    qpos[0], qvel[0] = data.qpos, data.qvel
    nxt, diverged, max_contacts = 1, None, int(data.ncon)
    for k in range(steps):
        crossing = nxt < len(times) and data.time + dt >= times[nxt] - 1e-9
        if crossing:
            before = (data.time, data.qpos.copy(), data.qvel.copy())
        if control == "sine":
            data.ctrl[:] = math.sin(data.time + dt / 2)
        mujoco.mj_step(model, data)
        max_contacts = max(max_contacts, int(data.ncon))
        if k % 50 == 49 or k == steps - 1:
            if np.any(data.warning.number) or not (np.all(np.isfinite(data.qpos)) and np.all(np.isfinite(data.qvel))):
                reason = ", ".join(f"{name} x{n}" for name, n in _warnings(data).items()) or "NaN or infinite state"
                if WARNINGS:
                    reason += f"; {WARNINGS[-1]}"
                diverged = {"time": float(data.time), "reason": reason}
                break
        while crossing and nxt < len(times) and data.time >= times[nxt] - 1e-9:
            w = min(max((times[nxt] - before[0]) / (data.time - before[0]), 0.0), 1.0)
            qpos[nxt] = (1 - w) * before[1] + w * data.qpos
            qvel[nxt] = (1 - w) * before[2] + w * data.qvel
            nxt += 1
    return {
        "t": times,
        "qpos": qpos,
        "qvel": qvel,
        "steps": steps,
        "timestep": dt,
        "integrator": _integrator(model),
        "diverged": diverged,
        "max_contacts": max_contacts,
    }


def _constraint_jacobian(model, data):
    """``efc_J`` as a dense nefc x nv array (MuJoCo stores it dense or row-sparse)."""
    import mujoco
    import numpy as np

    flat = np.asarray(data.efc_J).reshape(-1)
    if not mujoco.mj_isSparse(model):
        return flat[: data.nefc * model.nv].reshape(data.nefc, model.nv)
    J = np.zeros((data.nefc, model.nv))
    for r in range(data.nefc):
        start, count = int(data.efc_J_rowadr[r]), int(data.efc_J_rownnz[r])
        J[r, np.asarray(data.efc_J_colind[start:start + count], dtype=int)] = flat[start:start + count]
    return J


def tangent_acceleration(model, data) -> dict:
    """The acceleration along the only motion a one-degree-of-freedom closed loop allows, at the current state.

    ``t``: the unit null vector of the equality constraints' Jacobian (first clearly nonzero entry positive);
    ``alpha = t.T qfrc_smooth / (t.T M t)`` (M qacc = qfrc_smooth + J.T f, and J t = 0).  Exact whatever the
    softness of MuJoCo's constraints: ``qacc`` itself is not zero at rest even in a balanced configuration, since a
    soft constraint lets a small part of the unconstrained acceleration through.
    """
    import mujoco
    import numpy as np

    mujoco.mj_forward(model, data)
    rows = np.flatnonzero(np.asarray(data.efc_type) == int(mujoco.mjtConstraint.mjCNSTR_EQUALITY))
    if rows.size == 0:
        return {"error": "the model has no active equality constraint: nothing closes the loop"}
    J = _constraint_jacobian(model, data)[rows]
    _, s, Vt = np.linalg.svd(J)
    rank = int(np.sum(s > 1e-9 * max(1.0, s.max())))
    if model.nv - rank != 1:
        return {"error": f"the constrained model keeps {model.nv - rank} degrees of freedom, not one"}
    t = Vt[-1]
    t = t * np.sign(t[np.flatnonzero(np.abs(t) > 1e-9)[0]])
    Mt = np.zeros(model.nv)
    mujoco.mj_mulM(model, data, Mt, t)
    return {
        "alpha": float(t @ data.qfrc_smooth / (t @ Mt)),
        "tangent": t,
        "violation": float(np.max(np.abs(np.asarray(data.efc_pos)[rows]))),
        "qacc": data.qacc.copy(),
    }
