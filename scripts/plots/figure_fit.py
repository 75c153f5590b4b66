"""Save a figure only when every text on it can be read.

save_checked(fig, path, dpi=...) saves the figure and checks, on the very
draw that wrote the file, every suptitle, axes title, axis label, tick label,
text, annotation and legend: each must lie inside the figure (a title running
off the edge is cut in the PNG), and no two titles may overlap. When one does
not, it raises FigureTextError naming the figure file and the offending text,
and leaves no file at path; otherwise the file is in place. The figure is
closed either way. The PNG is byte for byte what fig.savefig(path, dpi=dpi)
writes (no extra draw: constrained layout moves by a pixel on each draw).
"""
from pathlib import Path

from matplotlib.text import Annotation

TOLERANCE_PX = 1.0  # rounding of the extents


class FigureTextError(ValueError):
    """A text of a figure lies (partly) outside it or overlaps another title."""


def _quoted(text, limit=70):
    text = " ".join(text.split())
    return repr(text if len(text) <= limit else text[:limit - 3] + "...")


def _texts(fig):
    """(what, artist) for every text the figure shows."""
    for text in fig.texts:
        yield ("suptitle" if text is getattr(fig, "_suptitle", None) else "figure text"), text
    for legend in fig.legends:
        yield "figure legend", legend
    for i, ax in enumerate(fig.axes):
        where = f"axes {i}"
        for title in (ax.title, ax._left_title, ax._right_title):
            yield f"{where} title", title
        yield f"{where} x label", ax.xaxis.label
        yield f"{where} y label", ax.yaxis.label
        for name, axis in (("x", ax.xaxis), ("y", ax.yaxis)):
            for label in _tick_labels(axis):
                yield f"{where} {name} tick label", label
        for text in ax.texts:
            yield f"{where} {'annotation' if isinstance(text, Annotation) else 'text'}", text
        if ax.get_legend() is not None:
            yield f"{where} legend", ax.get_legend()


def _tick_labels(axis):
    """The tick labels the axis draws (ticks outside its view are not drawn)."""
    ticks = axis._update_ticks() if hasattr(axis, "_update_ticks") else axis.get_major_ticks()
    for tick in ticks:
        for label in (tick.label1, tick.label2):
            if label.get_visible():
                yield label
    offset = axis.get_offset_text()
    if offset.get_visible():
        yield offset


def _label(artist):
    if hasattr(artist, "get_text"):
        return _quoted(artist.get_text())
    texts = [t.get_text() for t in artist.get_texts()]  # a legend
    title = artist.get_title().get_text()
    return _quoted((title + ": " if title else "") + ", ".join(texts))


def _shown(artist, renderer):
    if not artist.get_visible():
        return False
    if hasattr(artist, "get_text") and not artist.get_text().strip():
        return False
    # An annotation whose point lies outside its axes is not drawn.
    if isinstance(artist, Annotation) and not artist._check_xy(renderer):
        return False
    return True


def text_problems(fig, draw=True):
    """Lists what does not fit, one sentence each; draws the figure first
    unless it has just been drawn (saved) at its dpi."""
    if draw:
        fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    frame = fig.bbox
    problems, titles = [], []
    for what, artist in _texts(fig):
        if not _shown(artist, renderer):
            continue
        box = artist.get_window_extent(renderer)
        overhang = {"left": frame.x0 - box.x0, "right": box.x1 - frame.x1,
                    "bottom": frame.y0 - box.y0, "top": box.y1 - frame.y1}
        cut = [f"{side} by {px:.0f} px" for side, px in overhang.items() if px > TOLERANCE_PX]
        if cut:
            problems.append(f"{what} {_label(artist)} runs off the figure ({', '.join(cut)}; text "
                            f"{box.width:.0f} x {box.height:.0f} px, figure {frame.width:.0f} x {frame.height:.0f} px)")
        if what == "suptitle" or what.endswith(" title"):
            titles.append((what, artist, box))
    for i, (what, artist, box) in enumerate(titles):
        for other_what, other, other_box in titles[i + 1:]:
            width = min(box.x1, other_box.x1) - max(box.x0, other_box.x0)
            height = min(box.y1, other_box.y1) - max(box.y0, other_box.y0)
            if width > TOLERANCE_PX and height > TOLERANCE_PX:
                problems.append(f"{what} {_label(artist)} overlaps {other_what} {_label(other)}")
    return problems


def check(fig, path, draw=True):
    """Raises FigureTextError when a text of fig (saved as path) does not fit."""
    problems = text_problems(fig, draw)
    if problems:
        raise FigureTextError(f"figure {Path(path).name} ({path}): " + "; ".join(problems))


def save_checked(fig, path, dpi=None, **savefig_kwargs):
    """fig.savefig(path, dpi=dpi), kept only when check() finds every text in
    the figure; written whole or not at all (atomic_save.py); closes the
    figure either way."""
    import matplotlib.pyplot as plt

    from atomic_save import save_figure

    try:
        if dpi is not None:
            fig.set_dpi(dpi)  # the saving draw then leaves the layout in the file's pixels
        save_figure(fig, path, check=lambda: check(fig, path, draw=False),
                    dpi=dpi if dpi is not None else "figure", **savefig_kwargs)
    finally:
        plt.close(fig)
