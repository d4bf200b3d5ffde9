"""Problem 30 (Inheritance to Structure Code): the class diagram as data and the model answers.

(a) The v2 classes of the kinematic tree and their base classes (the sheet and problem data):
RigidBodyKinematicsCLASS_v2 -> RigidBodyDynamicsCLASS_v2 -> LinkedRigidBodyDynamicsCLASS_v2, which also inherits
from LinkedBodyObjectCLASS_v2; LinkedJointObjectCLASS_v2 -> LinkedGenericJointCLASS_v2 ->
LinkedRotationalJointCLASS_v2.  (b) is a comparison of files and has no answer to grade.
"""

__all__ = ["class_diagram", "base_classes", "ANSWER_C", "ANSWER_D", "ANSWER_E"]

ANSWER_C = (
    "Private members are visible only inside the class that defines them. Once the code is distributed over "
    "a hierarchy, the subclasses must use the members they inherit (e.g. the body's pose and velocities, the "
    "joint's predecessor and successor), so these members are made protected: still hidden from the outside, but "
    "accessible to subclasses."
)

ANSWER_D = (
    "It calls the constructor of the superclass LinkedGenericJointCLASS_v2 with (env, predBody, sucBody) on obj, "
    "so the inherited part of the object (environment, predecessor and successor bodies and their links) is "
    "initialised by the superclass before the subclass constructor continues; in Python: "
    "super().__init__(env, predBody, sucBody)."
)

ANSWER_E = (
    "LinkedJointObjectCLASS_v2 only links the bodies. LinkedGenericJointCLASS_v2 carries what all joint types "
    "share, the recursion that passes the kinematics from the predecessor across the joint to the successor, "
    "written in terms of a joint function (relative position and orientation of the joint frames). Each joint "
    "type (rotational, prismatic, rolling contact, ...) then inherits from the generic joint and only supplies "
    "its joint function instead of repeating the recursion."
)


def class_diagram():
    """(a): ``(subclass, base)`` pairs of the v2 classes, in the course's class names."""
    # TODO problem 30: write your solution here
    raise NotImplementedError("Problem 30: class_diagram is not implemented yet")


def base_classes(name):
    """All classes that ``name`` inherits from, directly or indirectly, according to ``class_diagram()``."""
    direct = [base for sub, base in class_diagram() if sub == name]
    return set(direct).union(*(base_classes(base) for base in direct))
