# %% [markdown]
# # Radiometric calibration, every step from Python
# The simulated field of grey panels (their reflectance known, truth.csv the true line): the
# frames stitched into a row, the row put on the map by its control points, the panels' DN
# measured on the row given as a numpy array and the line fitted, the row converted to
# reflectance and checked on the check surfaces — each step the core code `laserwb-cli
# radiometry mosaic | gcp | fit | apply | check` runs.

# %%
import csv
import os

import numpy as np

import laserwb
from _inputs import simulate, workdir

work = workdir()
field = os.path.join(work, "field")
simulate("radiometry", field)
frames = sorted(os.path.join(field, f) for f in os.listdir(field) if f.startswith("frame_"))

# %% The row: the frames stitched (keypoints, RANSAC, blending)
m = laserwb.radiometry.mosaic(frames)
row = os.path.join(work, "row.tif")
m.write(row)
for p in m.pairs:
    print(f"frames {p['from']}-{p['to']}: {p['inliers']}/{p['matches']} inliers, RMS {p['rms_px']:.3f} px")

# %% On the map: the control points' transform, the row resampled onto a north-up grid
g = laserwb.radiometry.gcp(row, os.path.join(field, "gcps.csv"))
print(g.fit["model"], f"RMS {g.fit['rms_px']:.3f} px,", g.fit["grid"])
g.write(os.path.join(work, "map.tif"))  # a GeoTIFF in the markers' local metre frame

# %% The row image as a numpy array, and the fit
image = laserwb.radiometry.read_image(row)
print(f"row image {image.shape}, DN {np.nanmin(image):.0f}..{np.nanmax(image):.0f}")
f = laserwb.radiometry.fit(os.path.join(field, "regions.csv"), image=image)
print(f.fit)
fit_csv = os.path.join(work, "fit.csv")
f.write_csv(fit_csv)

# %% Against the truth
t = next(csv.DictReader(open(os.path.join(field, "truth.csv"))))
print("true line:", t)

# %% DN to reflectance, and the check surfaces
a = laserwb.radiometry.apply(row, fit=fit_csv)
print(f"reflectance {np.nanmin(a.reflectance):.1f}..{np.nanmax(a.reflectance):.1f} %, "
      f"uncertainty up to {np.nanmax(a.uncertainty):.2f} %")
c = laserwb.radiometry.check(os.path.join(field, "check.csv"), image=a.reflectance)
for r in c.table["rows"]:
    print(f"{r['name']}: measured {r['measured_pct']:.2f} %, image {r['image_pct']:.2f} %, "
          f"error {r['relative_error_pct']:.2f} %")
print("all within 5 %:", c.table["all_within_limit"])
