# SPDX-License-Identifier: MIT
"""The examples whose reports the browser and LaTeX tests open: every examples/<name>/ with a
model script (model.alb, named <name>; model_<variant>.alb, named <name>_<variant>)."""
import os


def example_models(source):
    """[(name, path of its model script)] for every example with a model script, by name."""
    folder = os.path.join(source, "examples")
    found = []
    for d in sorted(os.listdir(folder)):
        if not os.path.isdir(os.path.join(folder, d)):
            continue
        for f in sorted(os.listdir(os.path.join(folder, d))):
            m = f[:-len(".alb")] if f.endswith(".alb") else None
            if m == "model":
                found.append((d, os.path.join(folder, d, f)))
            elif m and m.startswith("model_"):
                found.append((d + "_" + m[len("model_"):], os.path.join(folder, d, f)))
    return sorted(found)
