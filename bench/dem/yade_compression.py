# The compression benchmark's Yade side: the same particles, bonds, platens, time step,
# damping and number of steps as planter-dem, with Yade's cohesive-frictional law
# (CohFrictMat) mapped from the parallel-bond parameters (see
# ../shared/notes/dem-bonded-particles.md). Run by planter_bench_dem:
#   yade -n -x -j1 yade_compression.py MODEL_FILE
# MODEL_FILE holds "key value" lines, then "p x y z r" particles and "b i j" bonds.
import math
import sys
import time

from yade import O, utils
from yade.wrapper import (Bo1_Box_Aabb, Bo1_Sphere_Aabb, CohFrictMat, ForceResetter,
                          Ig2_Box_Sphere_ScGeom6D, Ig2_Sphere_Sphere_ScGeom6D, InsertionSortCollider,
                          InteractionLoop, Ip2_CohFrictMat_CohFrictMat_CohFrictPhys,
                          Law2_ScGeom6D_CohFrictPhys_CohesionMoment, NewtonIntegrator)

cfg, particles, bonds = {}, [], []
with open(sys.argv[1]) as f:
    for line in f:
        w = line.split()
        if not w:
            continue
        if w[0] == "p":
            particles.append(tuple(float(v) for v in w[1:5]))
        elif w[0] == "b":
            bonds.append((int(w[1]), int(w[2])))
        else:
            cfg[w[0]] = float(w[1])

r = particles[0][3]
rb = cfg["bond_radius"]
area = math.pi * rb * rb
seed = O.materials.append(CohFrictMat(
    young=cfg["normal_stiffness"] * area / r, poisson=cfg["shear_stiffness"] / cfg["normal_stiffness"],
    density=cfg["density"], frictionAngle=math.atan(cfg["friction"]),
    normalCohesion=cfg["tensile_strength"] * area / (r * r),
    shearCohesion=cfg["shear_strength"] * area / (r * r),
    momentRotationLaw=True, isCohesive=True,
    alphaKr=rb * rb / (4 * r * r), alphaKtw=rb * rb / (2 * r * r)))
steel = O.materials.append(CohFrictMat(
    young=cfg["platen_young"], poisson=cfg["platen_poisson"], density=7800,
    frictionAngle=math.atan(cfg["platen_friction"]), isCohesive=False, momentRotationLaw=False))

ids = [O.bodies.append(utils.sphere((x, y, z), rr, material=seed)) for x, y, z, rr in particles]
half = 0.2  # platens wider than the seedling
thick = 0.005
lower = O.bodies.append(utils.box((0, cfg["min_y"] - thick, 0), (half, thick, half), fixed=True,
                                  material=steel))
upper = O.bodies.append(utils.box((0, cfg["max_y"] + thick, 0), (half, thick, half), fixed=True,
                                  material=steel))
O.bodies[upper].state.vel = (0, -cfg["platen_speed"], 0)

# Bonds: interactions found at the bonding distance once, made cohesive, then the detection
# goes back to touching spheres.
factor = (2 * r + cfg["bond_gap"]) / (2 * r)
sphere_aabb = Bo1_Sphere_Aabb(aabbEnlargeFactor=factor)
sphere_geom = Ig2_Sphere_Sphere_ScGeom6D(interactionDetectionFactor=factor)
O.engines = [
    ForceResetter(),
    InsertionSortCollider([sphere_aabb, Bo1_Box_Aabb()], verletDist=0.2 * r),
    InteractionLoop([sphere_geom, Ig2_Box_Sphere_ScGeom6D()],
                    [Ip2_CohFrictMat_CohFrictMat_CohFrictPhys(setCohesionNow=True,
                                                              setCohesionOnNewContacts=False)],
                    [Law2_ScGeom6D_CohFrictPhys_CohesionMoment(useIncrementalForm=True,
                                                                always_use_moment_law=True)]),
    NewtonIntegrator(damping=cfg["damping"], gravity=(0, 0, 0)),
]
O.dt = cfg["dt"]
O.step()
sphere_aabb.aabbEnlargeFactor = -1
sphere_geom.interactionDetectionFactor = -1
cohesive = sum(1 for i in O.interactions if i.isReal and i.phys.cohesionBroken is False
               and i.id1 < len(ids) and i.id2 < len(ids))
steps = int(cfg["steps"]) - 1
checkpoints = int(cfg["checkpoints"])
t0 = time.perf_counter()
done = 0
for k in range(checkpoints):
    n = (steps * (k + 1)) // checkpoints - done
    O.run(n, True)
    done += n
    print("YADE_FORCE %d %.6g" % (done + 1, abs(O.forces.f(upper)[1])))
elapsed = time.perf_counter() - t0
print("YADE_RESULT particles=%d bonds=%d steps=%d seconds=%.6f" % (len(ids), cohesive, steps, elapsed))
sys.stdout.flush()
