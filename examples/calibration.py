# %% [markdown]
# # Altimeter calibration: detector array and statistics
# Simulated calibration inputs (exact truth beside them), run through the core's calibration
# task (`laserwb-cli calib detector` and `calib stats`).

# %%
import os

import laserwb
from _inputs import simulate, workdir

work = workdir()
calib = os.path.join(work, "calib")
simulate("calib", "--seed", 5, calib)

# %% The footprint centre from the detector array
params = laserwb.calib.CalibParams()
print(params.describe("detector.outlier_sigma"))
d = laserwb.calib.detector(os.path.join(calib, "detectors.csv"), params=params)
print(d.centre, d.doubts or "not doubtful")
print(open(os.path.join(calib, "detector_truth.csv")).read().strip())
d.write_centre(os.path.join(work, "centre.csv"))

# %% Validation statistics per beam
s = laserwb.calib.stats(os.path.join(calib, "diffs.csv"), group="beam")
for name, g in s.groups().items():
    print(f"{name}: n {g['n']:.0f}, mean {g['mean']:.3f} m, RMS about zero {g['rms_about_zero']:.3f} m")
s.write_csv(os.path.join(work, "stats.csv"))
