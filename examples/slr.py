# %% [markdown]
# # An SLR pass from Python
# A simulated LAGEOS-like CRD pass (the station's filter flags are the truth), loaded with its
# O-C, screened, fitted and reduced to normal points by the core's pass task (`laserwb-cli slr`).

# %%
import os

import numpy as np

import laserwb
from _inputs import simulate, workdir

work = workdir()
frd = os.path.join(work, "pass.frd")
simulate("slr", "--kind", "conventional", "--seed", 5, frd)
print(laserwb.slr.read_crd(frd)[0])

# %% The pass: epochs and O-C as numpy arrays
p = laserwb.slr.load_pass(frd)
print(p, f"O-C spread {np.ptp(p.oc) * 1e9:.1f} ns")

# %% Screening, post-fit and normal points, with one parameter changed
r = laserwb.slr.run(p, params={"screen.cosine_c": 0.95, "postfit.reject_sigma": 3})
truth = p.station_flag == 2
found = r.accepted  # a bool mask: p.t[found] are the accepted epochs
print(f"accepted {r.accepted_count} of {len(p)}; recall {np.sum(found & truth) / np.sum(truth):.3f}, "
      f"precision {np.sum(found & truth) / max(np.sum(found), 1):.3f}; RMS {r.rms_s * 1e12:.1f} ps")
print(f"{len(r.normal_points['epoch_s'])} normal points" + (f" ({r.no_normal_points_reason})" if r.doubt else ""))

# %% The products, by the CLI's writers
r.write(csv=os.path.join(work, "screened.csv"), crd=os.path.join(work, "flagged.frd"), npt=os.path.join(work, "pass.npt"))
print("->", work)
