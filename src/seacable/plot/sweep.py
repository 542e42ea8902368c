"""Standard figure of a sweep's summary: the design figures against the swept parameters.

One panel for the tensions (maximum and minimum top tension, maximum and minimum tension
anywhere) and one per figure of the model (:data:`seacable.extremes.KEY_FIGURES`: entry angle and
layback of a lay, barge tension of a tow, ...), against the first numeric swept parameter. With
more parameters, each combination of the others is one curve. Failed cases are left out and
counted in the title.
"""

from __future__ import annotations

import json

import numpy as np

from ._core import _label

__all__ = ["SWEEP_FIGURES"]

_TENSIONS = (("top_tension_max", "top, max", "-"), ("top_tension_min", "top, min", "--"),
             ("tension_max", "anywhere, max", ":"), ("tension_min", "anywhere, min", "-."))


def _axis(ds, params):
    """The parameter along the x axis (the first numeric one that varies) and the others that vary."""
    params = [p for p in params if len(set(ds[p].values.tolist())) > 1] or params[:1]
    numeric = [p for p in params if ds[p].dtype.kind in "fiu"]
    x = numeric[0] if numeric else params[0]
    return x, [p for p in params if p != x]


def _groups(ds, others):
    """Case indices of each combination of the other parameters, with its label."""
    if not others:
        return [(np.arange(ds.sizes["case"]), "")]
    keys = list(zip(*(ds[p].values.tolist() for p in others)))
    out = []
    for key in dict.fromkeys(keys):
        idx = np.array([i for i, k in enumerate(keys) if k == key])
        out.append((idx, ", ".join(f"{p.rsplit('.', 1)[-1]} = {v:g}" if isinstance(v, float) else
                                   f"{p.rsplit('.', 1)[-1]} = {v}" for p, v in zip(others, key))))
    return out


def _sweep(ds, plt):
    from ..extremes import KEY_FIGURES

    params = json.loads(ds.attrs["parameters"])
    xname, others = _axis(ds, params)
    xvals = ds[xname].values
    own = [k for k in KEY_FIGURES.get(ds.attrs.get("case_analysis"), ()) if k in ds]
    tensions = [t for t in _TENSIONS if t[0] in ds]
    panels = ([None] if tensions else []) + own
    if not panels:
        panels = [k for k, v in ds.data_vars.items() if v.dtype.kind == "f" and k != "wall_time"][:4]
    ncol = 2 if len(panels) == 4 else min(len(panels), 3) or 1
    nrow = -(-max(len(panels), 1) // ncol)
    fig, axes = plt.subplots(nrow, ncol, figsize=(4.6 * ncol, 3.8 * nrow), squeeze=False)
    groups = _groups(ds, others)
    numeric_x = xvals.dtype.kind in "fiu"
    for ax, panel in zip(axes.flat, panels):
        for g, (idx, label) in enumerate(groups):
            order = idx[np.argsort(xvals[idx])] if numeric_x else idx
            color = f"C{g % 10}"
            if panel is None:
                for name, what, style in tensions:
                    ax.plot(xvals[order], ds[name].values[order] / 1e3, style, marker=".", color=color,
                            label=f"{what}{' (' + label + ')' if label else ''}" if g == 0 or label else None)
                ax.set_ylabel("tension [kN]")
            else:
                ax.plot(xvals[order], ds[panel].values[order], "-", marker="o", ms=3, color=color,
                        label=label or None)
                units = _label(ds[panel]).rpartition(" [")[2]
                ax.set_ylabel(f"{panel} [{units}" if units != _label(ds[panel]) else panel)
                ax.set_title(ds[panel].attrs.get("long_name", panel), fontsize=9)
        ax.set_xlabel(_label(ds[xname]))
        ax.grid(alpha=0.3)
        if panel is None:
            ax.set_title("Tensions", fontsize=9)
            ax.legend(fontsize=7)
        elif len(groups) > 1:
            ax.legend(fontsize=7)
    for ax in list(axes.flat)[len(panels):]:
        ax.set_visible(False)
    failed = int(np.sum(ds["status"].values == "failed"))
    not_run = int(np.sum(ds["status"].values == "not run"))
    note = "".join([f", {failed} failed" if failed else "", f", {not_run} not run" if not_run else ""])
    fig.text(0.01, 0.005, f"{ds.sizes['case']} cases{note}", fontsize=8)
    return {"sweep": fig}


SWEEP_FIGURES = {"sweep": _sweep}
