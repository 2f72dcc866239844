"""What the contact adapters share (docs/clients.md, "Contact scenes"): the scene of two spheres
touching along x that every code here can represent, and the central preload that bonds them.

A granular contact only pushes; the scene's pulls as well. Each adapter presses the spheres together
by a constant pull F0 along the line of their centres, from the overlap F0 / k_n where pull and
spring balance, and writes the positions back shifted by half that overlap each. About that
equilibrium the contact is the scene's while it stays closed: the overlap is 3000 times the
perturbation's amplitude, which the stability criterion (energy by 1e6, amplitude by 1e3) does not
reach. The pull is central, as the contact's push is, so the two cancel across the contact too (a
pull fixed along x buckles the pair: its rotation grew 25-fold in energy per 100 steps of 1e-4 s).
Python 3 stdlib only; imported by lammps/lammps_contact.py, yade/yade_contact.py and
kratos/kratos_contact.py from the folder above theirs.
"""
import math
import os
import sys


def decline(why):  # a scene this code cannot represent: exit 3, in the adapter's name
    print("%s: %s" % (os.path.basename(sys.argv[0]), why), file=sys.stderr)
    sys.exit(3)


def sphere_pair(spec, law):
    """The bodies, the contact, the radii and the reduced mass of a scene of two spheres touching
    along x; any other scene is declined, naming the code's `law`."""
    bodies, contact = spec["bodies"], spec["contact"]
    for b in bodies:
        if b["shape"]["kind"] != "sphere":
            decline("%s acts between spheres, not a body of kind '%s'" % (law, b["shape"]["kind"]))
    if contact["normal"] != [1.0, 0.0, 0.0] or any(abs(b["position"][1]) + abs(b["position"][2]) > 0 for b in bodies):
        decline("the spheres must touch along x (the scene's normal is %s)" % contact["normal"])
    m1, m2 = bodies[0]["mass"], bodies[1]["mass"]
    return bodies, contact, [b["shape"]["size"][0] for b in bodies], m1 * m2 / (m1 + m2)


def preload_overlap(bodies, contact, radii, meff):
    """The preload's overlap: 3000 times the perturbation's amplitude, |relative velocity at the
    contact| / sqrt(k / meff) with the softer spring; declined past 1 % of a radius."""
    rel = [bodies[1]["velocity"][k] - bodies[0]["velocity"][k] for k in range(3)]
    spin = [abs(bodies[0]["omega_world"][k]) * radii[0] + abs(bodies[1]["omega_world"][k]) * radii[1] for k in range(3)]
    stiffness = min(contact["normal_stiffness"], contact["tangential_stiffness"])
    overlap = 3000.0 * (math.sqrt(sum(v * v for v in rel)) + math.sqrt(sum(s * s for s in spin))) / math.sqrt(stiffness / meff)
    if overlap > 0.01 * min(radii):
        decline("the preload's overlap %r would be more than 1 %% of a radius" % overlap)
    return overlap
