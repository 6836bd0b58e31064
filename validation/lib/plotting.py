"""Figure helpers shared by the validation scripts (matplotlib, headless)."""


def pyplot():
    """matplotlib.pyplot on the Agg backend (no display on CI or the cluster)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def plot_history(ax, history, style, label, **kw):
    """One front history, [[t, front], ...], on an axis."""
    ax.plot([a for a, _ in history], [b for _, b in history], style, label=label, **kw)


def front_axes(ax, title, fontsize=8):
    """Title, labels, legend and grid of a front-travel-against-time panel."""
    ax.set_title(title)
    ax.set_xlabel("t [s]")
    ax.set_ylabel("front travel [m]")
    ax.legend(fontsize=fontsize)
    ax.grid(alpha=0.3)
