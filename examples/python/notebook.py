# %% [markdown]
# # urdfsnap in a notebook
# A notebook-style script (`# %%` cells: VS Code, Jupytext and Spyder run them one by one; `python3
# notebook.py` runs them all). In Jupyter each image shows inline; as a script the images are
# written to output/notebook_*.png instead. Run from the repository root.

# %%
import pathlib

import numpy as np

import urdfsnap

robot = urdfsnap.Robot("models/mrm_description/urdf/mrm.urdf")
print(robot.name, "links:", robot.links)
print("joints:", [(j.name, j.type, j.lower, j.upper) for j in robot.joints])
robot  # in Jupyter: the default view, inline (Robot._repr_png_)

# %%
image = robot.render({"link_01__link_02": -0.6, "link_02__link_03": 1.2}, yaw=1.0, pitch=0.4, fit=True)
print(image.shape, image.dtype)  # (480, 640, 3) uint8
shown = urdfsnap.show(image)

# %% Depth and link labels from the same view
result = robot.render({"link_01__link_02": -0.6}, fit=True, depth=True, labels=True, size=(320, 240))
near, far = np.nanmin(result.depth), np.nanmax(result.depth)
print(f"the robot is {near:.2f} m to {far:.2f} m from the camera")
seen = np.unique(result.labels[result.labels > 0])
print("links seen:", [result.label_names[k] for k in seen])
# depth as grey (near white, far dark, background black) beside the colour image
grey = np.where(np.isnan(result.depth), 0, 255 * (far - result.depth) / max(far - near, 1e-9) * 0.8 + 40)
depth_picture = np.repeat(grey.astype(np.uint8)[:, :, None], 3, axis=2)
both = urdfsnap.show(np.concatenate([result.color, depth_picture], axis=1))

# %% A joint swept through its range, as a strip
lower, upper = -1.5, 1.5
frames = robot.render_many([{"link_01__link_02": v} for v in np.linspace(lower, upper, 6)], size=(160, 120), fit=True)
strip = urdfsnap.show(np.concatenate(list(frames), axis=1))

# %% Outside a notebook: write what the cells showed
if shown is not None:
    out = pathlib.Path("output")
    out.mkdir(exist_ok=True)
    for name, picture in {"view": image, "depth": np.concatenate([result.color, depth_picture], axis=1),
                          "sweep": np.concatenate(list(frames), axis=1)}.items():
        urdfsnap.write_png(picture, out / f"notebook_{name}.png")
        print("wrote", out / f"notebook_{name}.png")
