"""Load a mesh, sample grasps with the bundled model, simulate them, save them for Isaac Sim."""
import sys

import graspecmf

mesh = "data/acronym-sample/meshes/Mug/10f6e09036350e92b3f21f1137c3c347.obj"
scale = 0.0002682457830986903  # this mesh's units to metres
out = sys.argv[1] if len(sys.argv) > 1 else "grasps.yaml"

model = graspecmf.GraspModel.load()  # the bundled mug model
grasps = model.sample(mesh=mesh, scale=scale, num=20, seed=0, reject_collisions=True)
result = graspecmf.simulate(mesh, grasps, scale=scale)
print(f"{result['success'].sum()} of {len(grasps)} grasps held the mug in simulation")
graspecmf.write_grasps(out, grasps, success=result["success"])  # Isaac Sim's isaac_grasp YAML
print(f"wrote {out}")
