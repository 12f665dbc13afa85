# %% [markdown]
# # DN to reflectance
# The simulated field of grey panels (their reflectance known, truth.csv the true line): the
# panels' DN measured on an image given as a numpy array, and the line fitted by the core
# (`laserwb-cli radiometry fit --image`).

# %%
import csv
import os
import subprocess

import numpy as np

import laserwb
from _inputs import CLI, simulate, workdir

work = workdir()
field = os.path.join(work, "field")
simulate("radiometry", field)
row = os.path.join(work, "row.tif")
frames = sorted(os.path.join(field, f) for f in os.listdir(field) if f.startswith("frame_"))
subprocess.run([CLI, "radiometry", "mosaic", *frames, "-o", row, "-q"], check=True)

# %% The row image as a numpy array, and the fit
image = laserwb.radiometry.read_image(row)
print(f"row image {image.shape}, DN {np.nanmin(image):.0f}..{np.nanmax(image):.0f}")
f = laserwb.radiometry.fit(os.path.join(field, "regions.csv"), image=image)
print(f.fit)

# %% Against the truth
t = next(csv.DictReader(open(os.path.join(field, "truth.csv"))))
print("true line:", t)
f.write_csv(os.path.join(work, "fit.csv"))
