"""A numpy reader of the Oxford VGG multi-view sequences (Model House, Corridor, Merton College
I-III, University Library, Wadham College), as the C++ support library reads them
(modules/tripose/support/src/vgg_dataset.cpp).

A sequence folder holds per view <stem>.P (3x4 camera matrix), <stem>.corners ("x y" rows) and
<stem>.lines ("x0 y0 x1 y1"; Model House adds two columns), and per sequence <prefix>p3d,
<prefix>l3d, <prefix>nview-corners and <prefix>nview-lines, where <prefix> is "house.", "bt." or
empty. Row i of an nview file gives, per view in image order, the 0-based row of 3D feature i in
that view's file, '*' where the view does not see it.
"""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import List

import numpy as np


def read_table(path: Path, cols: int, at_least: bool = False, missing: bool = False) -> np.ndarray:
    """Rows of numbers (a '*' is -1 where missing is allowed); extra columns dropped if at_least."""
    rows = []
    for number, line in enumerate(Path(path).read_text().splitlines(), 1):
        items = line.split()
        if not items:
            continue
        if len(items) != cols and not (at_least and len(items) > cols):
            raise ValueError(f"{path}: line {number}: expected {'at least ' if at_least else ''}{cols} values, "
                             f"got {len(items)}")
        try:
            rows.append([-1.0 if (missing and v == "*") else float(v) for v in items[:cols]])
        except ValueError as error:
            raise ValueError(f"{path}: line {number}: {error}") from None
    return np.array(rows, dtype=np.float64).reshape(-1, cols)


def view_stems(folder: Path) -> tuple:
    """The views' file stems in image order and the sequence's file prefix."""
    cameras = sorted(Path(folder).glob("*.P"))
    if not cameras:
        raise FileNotFoundError(f"{folder} holds no camera matrix files (*.P)")
    stems = [str(p)[:-2] for p in cameras]
    name = cameras[0].name[:-2]
    # "bt.003" -> "<folder>/bt.", "001" -> "<folder>/"
    prefix = str(Path(folder) / "x")[:-1] + (name[:name.rfind(".") + 1] if "." in name else "")
    return stems, prefix


def rq(M: np.ndarray) -> tuple:
    """M = U Q with U upper triangular (positive diagonal) and Q orthogonal."""
    flip = np.eye(3)[::-1]
    q, r = np.linalg.qr((flip @ M).T)
    U = flip @ r.T @ flip
    Q = flip @ q.T
    signs = np.diag(np.sign(np.diag(U)))
    return U @ signs, signs @ Q


def decompose(P: np.ndarray) -> tuple:
    """P = lambda K [R | t] with K(2, 2) = 1 and lambda > 0 (det(P[:, :3]) > 0 made by the caller)."""
    U, Q = rq(P[:, :3])
    if not np.all(np.diag(U) > 0) or np.linalg.det(Q) <= 0:
        raise ValueError("the camera matrix is singular or its world frame is left-handed")
    t = np.linalg.solve(U, P[:, 3])
    K = np.triu(U / U[2, 2])
    K[2, 2] = 1.0
    return K, Q, t


@dataclass
class Triplet:
    K: List[np.ndarray]           # one camera matrix per view
    R12: np.ndarray               # pose of view 2 in the frame of view 1
    t12: np.ndarray
    R: np.ndarray                 # pose of view 3 in the frame of view 1 (the sequence's camera)
    t: np.ndarray
    points: List[np.ndarray]      # (N, 2) per view: the corners seen in all three views
    lines: List[np.ndarray]       # (M, 4) per view: the segments seen in all three views


def load_triplet(folder, views=(0, 1, 2)) -> Triplet:
    """Three views of a sequence with the points and lines that all three see, in the frame of the
    first of them."""
    stems, prefix = view_stems(Path(folder))
    if len(set(views)) != 3 or not all(0 <= v < len(stems) for v in views):
        raise ValueError(f"views must be three distinct views of the {len(stems)} of {folder}, got {views}")
    p3d = read_table(Path(prefix + "p3d"), 3)
    l3d = read_table(Path(prefix + "l3d"), 6)
    nview_corners = read_table(Path(prefix + "nview-corners"), len(stems), missing=True)
    nview_lines = read_table(Path(prefix + "nview-lines"), len(stems), missing=True)

    cameras = []
    for v in views:
        P = read_table(Path(stems[v] + ".P"), 4)
        # The sign of P that puts the structure this view sees in front of it.
        seen_points = p3d[nview_corners[:, v] >= 0]
        seen_lines = l3d[nview_lines[:, v] >= 0].reshape(-1, 3)
        X = np.vstack([seen_points, seen_lines])
        depth = np.c_[X, np.ones(len(X))] @ P[2]
        if np.sum(depth < 0) > np.sum(depth > 0):
            P = -P
        cameras.append(P)
    mirrored = [np.linalg.det(P[:, :3]) < 0 for P in cameras]
    if len(set(mirrored)) != 1:
        raise ValueError(f"{folder}: the views' world frames differ in handedness")
    # A mirrored (left-handed) world frame is read with Z flipped: P' = P diag(1, 1, -1, 1).
    flip = np.diag([1.0, 1.0, -1.0 if mirrored[0] else 1.0, 1.0])
    K, Rw, tw = zip(*(decompose(P @ flip) for P in cameras))

    R12 = Rw[1] @ Rw[0].T
    R13 = Rw[2] @ Rw[0].T
    point_ids = np.flatnonzero(np.all(nview_corners[:, list(views)] >= 0, axis=1))
    line_ids = np.flatnonzero(np.all(nview_lines[:, list(views)] >= 0, axis=1))
    points, lines = [], []
    for v in views:
        corners = read_table(Path(stems[v] + ".corners"), 2, at_least=True)
        segments = read_table(Path(stems[v] + ".lines"), 4, at_least=True)
        points.append(corners[nview_corners[point_ids, v].astype(int)])
        lines.append(segments[nview_lines[line_ids, v].astype(int)])
    return Triplet(list(K), R12, tw[1] - R12 @ tw[0], R13, tw[2] - R13 @ tw[0], points, lines)
