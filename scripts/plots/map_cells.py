"""The cells of a map drawn with pcolormesh over sorted axis values."""
import numpy as np


def cell_edges(centres, half_width):
    """The cells' edges around sorted centres: midway between neighbours, a
    neighbour's half-step (or `half_width` for a lone value, which
    pcolormesh's "nearest" cannot size) beyond the ends."""
    c = np.asarray(centres, dtype=float)
    if len(c) == 1:
        return np.array([c[0] - half_width, c[0] + half_width])
    middle = (c[1:] + c[:-1]) / 2
    return np.concatenate([[c[0] - (middle[0] - c[0])], middle, [c[-1] + (c[-1] - middle[-1])]])
