# One run of sylvarock's exported scene in Yade (run inside Yade: yade -n -x yade_run.py DIR DT OUT).
# DIR is what `sylvarock scene export` wrote: the soil spheres are fixed, the block is a clump of
# its spheres carrying the true solid's mass and inertia (release.csv), the block/soil law is Yade's
# ViscElMat with the K_n, K_t and alpha that sylvarock applies (soil_contact.csv). The run ends as
# sylvarock's BlockRun ends it: the centre leaves the soil bed's extent, or stays within
# rest_distance of one point for rest_time once it has landed, or max_time passes.
import csv
import json
import math
import sys

scene_dir, dt, out_prefix = sys.argv[1], float(sys.argv[2]), sys.argv[3]
rest_distance, rest_time, max_time, sample_interval = 0.05, 1.0, 300.0, 0.05


def rows(name):
    with open(f"{scene_dir}/{name}") as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


release = rows("release.csv")[0]
law = rows("soil_contact.csv")[0]
if law["normal_force_floored"] != 1:
    sys.exit("Yade's ViscEl law floors the normal force at zero: export with --set soil.dashpot_pulls=false")

# Yade combines the two materials' coefficients in series (1/k = 1/k1 + 1/k2): twice each gives the law.
material = ViscElMat(kn=2 * law["kn_n_m"], ks=2 * law["kt_n_m"], cn=2 * law["damping_n_s"], cs=0,
                     frictionAngle=math.radians(law["friction_deg"]), density=2700)
O.materials.append(material)
# The soil spheres overlap their neighbours: group mask 2 and the collider's avoidSelfInteractionMask
# keep Yade from building (and computing every step) ~440 000 soil/soil contacts that sylvarock never has.
SOIL_MASK, BLOCK_MASK = 2, 3
O.bodies.append([sphere((s["x"], s["y"], s["z"]), s["r"], fixed=True, material=material, mask=SOIL_MASK)
                 for s in rows("soil_spheres.csv")])

q = Quaternion(release["qw"], release["qx"], release["qy"], release["qz"])
centre = Vector3(release["x"], release["y"], release["z"])
members = [sphere(centre + q * Vector3(s["x"], s["y"], s["z"]), s["r"], material=material, mask=BLOCK_MASK)
           for s in rows("block_spheres.csv")]
clump_id, member_ids = O.bodies.appendClumped(members)
block = O.bodies[clump_id]
# The clump's own mass and inertia would come from its overlapping spheres; sylvarock uses the solid's.
# The cube's inertia is isotropic, so the principal frame Yade chose for the clump does not matter.
inertia = (release["ixx_kg_m2"], release["iyy_kg_m2"], release["izz_kg_m2"])
if max(inertia) - min(inertia) > 1e-9 * max(inertia):
    sys.exit("only blocks with an isotropic inertia (cube, sphere) are supported by this script")
block.state.mass = release["mass_kg"]
block.state.inertia = Vector3(*inertia)
block.state.pos = centre

O.engines = [
    ForceResetter(),
    InsertionSortCollider([Bo1_Sphere_Aabb()], avoidSelfInteractionMask=SOIL_MASK),
    InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_ViscElMat_ViscElMat_ViscElPhys()], [Law2_ScGeom_ViscElPhys_Basic()]),
    NewtonIntegrator(damping=0, gravity=(0, 0, -law["gravity_m_s2"])),
]
O.dt = dt

trajectory, state = [], {"landed": False, "anchor": None, "since": 0.0, "max_speed": 0.0, "reason": None}
check_every = max(1, int(round(0.01 / dt)))
sample_every = max(1, int(round(sample_interval / dt)))


def touching():
    return any(i.isReal for m in member_ids for i in O.interactions.withBody(m))


while state["reason"] is None:
    O.run(check_every, True)
    t, p, v = O.time, block.state.pos, block.state.vel
    state["max_speed"] = max(state["max_speed"], v.norm())
    if O.iter % sample_every == 0:
        w = block.state.angVel
        trajectory.append((t, p[0], p[1], p[2], v[0], v[1], v[2], w[0], w[1], w[2]))
    if not (release["xmin"] <= p[0] <= release["xmax"] and release["ymin"] <= p[1] <= release["ymax"]):
        state["reason"] = "left_domain"
        break
    state["landed"] = state["landed"] or touching()
    if state["landed"]:
        if state["anchor"] is None or (p - state["anchor"]).norm() > rest_distance:
            state["anchor"], state["since"] = Vector3(p), t
        if t - state["since"] >= rest_time:
            state["reason"] = "rest"
    if t >= max_time:
        state["reason"] = "time_limit"

p = block.state.pos
with open(out_prefix + ".csv", "w") as f:
    f.write("t,x,y,z,vx,vy,vz,wx,wy,wz\n")
    for r in trajectory:
        f.write(",".join(f"{x:.6f}" for x in r) + "\n")
with open(out_prefix + ".json", "w") as f:
    json.dump({"stop_x": p[0], "stop_y": p[1], "stop_z": p[2], "stop_reason": state["reason"], "duration_s": O.time,
               "max_speed_m_s": state["max_speed"], "release_x": release["x"], "release_y": release["y"],
               "release_z": release["z"], "dt_s": dt}, f)
