"""A rendered video with exact ground truth: a walk around a courtyard of textured planes.

The scene is a closed courtyard (11 m x 6.4 m, walls 6 m high, a sky above) whose walls are building
fronts cut from the real photographs of the shared data (Strecha's Herz-Jesus-P8 and fountain-P11):
stone, brick and plaster walls with recessed doors and windows (their reveals give straight depth
edges), a protruding church portal with steps in front of it, a fountain against the opposite wall,
a pillar and a bench standing free, a cobbled ground. A camera 1.6 m above the ground walks an
ellipse around the courtyard's middle at about 1 m/s, looking where it goes with gentle turns of the
head, and is back at its start after 300 frames at 30 frames per second: a loop.

Every view is rendered exactly: each quad is warped into the camera by the homography of its plane
(cv2.warpPerspective), and visibility is decided per sample by a z-buffer of inverse depth, which is
affine in the pixel coordinates over a plane. Views are rendered at twice the size and reduced by
area averaging (anti-aliased edges); textures are sampled from the mipmap level that matches their
reduction. Optional sensor noise is seeded.

Written sequence (the layout tripose-track / tripose_track read):

    left/000000.png ...          the left (or only) camera's frames, 640x480 colour PNG
    right/000000.png ...         with --stereo: the right camera's, BASELINE to the right
    left.txt, right.txt          list files "timestamp path" (seconds, as in groundtruth.txt)
    calib.yml                    mono: K, dist, R12, t12 (frame 1's pose in frame 0's camera);
                                 stereo: K, dist, R12, t12 of the rig (the right camera in the left's)
    calib_mono.yml               with --stereo: the mono calibration, to track the left frames alone
    groundtruth.txt              TUM (timestamp tx ty tz qx qy qz qw, camera to world) of the left
                                 camera, the world being frame 0's camera, metres

Tracking the list files gives trajectories stamped like the ground truth (a folder is stamped with
the frames' indices instead):

    python test/evaluation/render_sequence.py --output DIR --frames 300 [--stereo] [--seed 0]
    build/samples/tripose_track --images DIR/left.txt [--right DIR/right.txt] --calib DIR/calib.yml \\
        --output trajectory.txt

The textures need the shared data beside the checkout (test/python/real_sequences.py data_dir()).
"""
from __future__ import annotations

import argparse
import math
import sys
import time
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

import cv2
import numpy as np

REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(REPO / "test" / "python"))
import real_sequences as rs  # noqa: E402

FPS = 30.0
WIDTH, HEIGHT = 640, 480
K = np.array([[500.0, 0.0, 319.5], [0.0, 500.0, 239.5], [0.0, 0.0, 1.0]])
BASELINE = 0.12  # m: the right camera's centre along the left camera's x axis
LOOP_FRAMES = 300  # the walk returns to its start after this many frames
SUPERSAMPLE = 2  # views are rendered this many times larger and reduced by area averaging
PX_PER_M = 200  # texture resolution in the scene
NEAR = 0.01  # m: quads are clipped to this depth in front of the camera when bounding their image
NOISE = 1.0  # grey levels: default standard deviation of the sensor noise

# The courtyard: x from -HALF_LENGTH to HALF_LENGTH, y from -HALF_WIDTH to HALF_WIDTH, z up.
HALF_LENGTH, HALF_WIDTH, WALL_HEIGHT = 5.5, 3.2, 6.0
# The walk: an ellipse of these half-axes (m) around the courtyard's middle, at eye height.
WALK_A, WALK_B, EYE_HEIGHT = 2.0, 1.2, 1.6


# --- textures from the photographs ---------------------------------------------------------------

HERZ = "strecha-Herz-Jesus-P8/images/"
FOUNTAIN = "strecha-fountain-P11/images/"

# Fronto-parallel parts of the photographs: (image under the real-image data, x0, y0, x1, y1 in px).
MATERIALS = {
    "stone_a": (HERZ + "0006.jpg", 560, 0, 990, 880),
    "stone_b": (HERZ + "0004.jpg", 1230, 60, 1600, 1560),
    "stone_c": (HERZ + "0006.jpg", 1900, 0, 2180, 560),
    "stone_d": (HERZ + "0006.jpg", 1960, 580, 2220, 1560),
    "stone_f": (HERZ + "0005.jpg", 850, 0, 1190, 1700),
    "brick_a": (FOUNTAIN + "0005.jpg", 0, 0, 560, 1640),
    "brick_b": (FOUNTAIN + "0005.jpg", 2260, 0, 2760, 1620),
    "brick_c": (FOUNTAIN + "0000.jpg", 1830, 0, 2420, 1650),
    "brick_d": (FOUNTAIN + "0002.jpg", 2060, 0, 2760, 1640),
    "plaster": (FOUNTAIN + "0000.jpg", 0, 450, 590, 1580),
    "window_a": (HERZ + "0000.jpg", 420, 200, 690, 780),
    "window_b": (FOUNTAIN + "0000.jpg", 60, 0, 500, 430),
    "arcade_a": (HERZ + "0006.jpg", 2230, 190, 2800, 520),
    "arcade_b": (HERZ + "0006.jpg", 0, 0, 560, 290),
    "door_a": (HERZ + "0006.jpg", 1190, 1040, 1610, 1595),
    "door_b": (HERZ + "0004.jpg", 1790, 985, 2170, 1570),
    "door_c": (HERZ + "0004.jpg", 400, 1000, 850, 1570),
    "portal": (HERZ + "0004.jpg", 1570, 370, 2620, 1600),
    "relief": (HERZ + "0006.jpg", 1280, 60, 1610, 560),
    "fountain": (FOUNTAIN + "0005.jpg", 230, 0, 2330, 1880),
    "plinth_a": (HERZ + "0004.jpg", 1100, 1610, 1500, 1790),
    "plinth_b": (HERZ + "0006.jpg", 180, 1610, 440, 1780),
    "cobbles_a": (HERZ + "0004.jpg", 0, 1850, 3072, 2048),
    "cobbles_b": (HERZ + "0006.jpg", 0, 1830, 3072, 2048),
    "cobbles_c": (HERZ + "0007.jpg", 0, 1840, 3072, 2048),
}
# Materials whose photographed parts are things (a door, a window, a portal) rather than surfaces:
# they are stretched to the size asked for instead of cut to its aspect.
OBJECTS = {"window_a", "window_b", "arcade_a", "arcade_b", "door_a", "door_b", "door_c", "portal", "relief",
           "fountain"}
# Ground textures: the photographs see the ground at a grazing angle, so their rows are stretched
# by this factor to make the cobbles about as deep as wide.
GROUND_STRETCH = 2.0


@lru_cache(maxsize=None)
def photograph(relative):
    """The colour photograph at @p relative under the real-image data (read once)."""
    path = rs.data_dir() / relative
    image = cv2.imread(str(path), cv2.IMREAD_COLOR)
    if image is None:
        raise rs.DataMissing(f"{path}: cannot be read")
    return image


def material(name, width_m, height_m, at=0.0, flip=False):
    """The photograph's part named @p name as a texture of width_m x height_m at PX_PER_M, mirrored
    left to right with @p flip. A surface's texture is the largest piece of the part with the asked
    aspect, @p at (0 to 1) choosing where along the part it is cut, scaled alike in both directions;
    a thing's (OBJECTS) is the whole part stretched to the size."""
    relative, x0, y0, x1, y1 = MATERIALS[name]
    crop = photograph(relative)[y0:y1, x0:x1]
    if name.startswith("cobbles"):
        crop = cv2.resize(crop, (crop.shape[1], round(crop.shape[0] * GROUND_STRETCH)), interpolation=cv2.INTER_CUBIC)
    if name not in OBJECTS:
        h, w = crop.shape[:2]
        aspect = width_m / height_m
        cw, ch = (w, min(h, round(w / aspect))) if w / h < aspect else (min(w, round(h * aspect)), h)
        ox, oy = round(at * (w - cw)), round(at * (h - ch))
        crop = crop[oy:oy + ch, ox:ox + cw]
    size = (max(2, round(width_m * PX_PER_M)), max(2, round(height_m * PX_PER_M)))
    shrinking = size[0] * size[1] < crop.shape[0] * crop.shape[1]
    image = cv2.resize(crop, size, interpolation=cv2.INTER_AREA if shrinking else cv2.INTER_CUBIC)
    return image[:, ::-1].copy() if flip else image


def framed(image, border_m, shade=0.25):
    """@p image with a dark border of @p border_m around it: a window's frame."""
    out = image.copy()
    b = max(1, round(border_m * PX_PER_M))
    dark = (out.astype(np.float32) * shade).astype(np.uint8)
    for region in (np.s_[:b, :], np.s_[-b:, :], np.s_[:, :b], np.s_[:, -b:]):
        out[region] = dark[region]
    return out


def sky():
    """A smooth light sky, brighter towards one side (no features)."""
    w, h = 64, 64
    ramp = np.linspace(0.0, 1.0, w, dtype=np.float32)[None, :, None]
    top, bottom = np.array([225, 205, 190], np.float32), np.array([245, 235, 228], np.float32)
    image = top + (bottom - top) * ramp
    return np.repeat(image, h, axis=0).astype(np.uint8)


def mipmap(image):
    """The texture's levels: the image, then halved by area averaging while its sides reach 16 px
    (each level spans the whole texture, odd sides rounded up)."""
    levels = [image]
    while min(levels[-1].shape[:2]) >= 16:
        h, w = levels[-1].shape[:2]
        levels.append(cv2.resize(levels[-1], ((w + 1) // 2, (h + 1) // 2), interpolation=cv2.INTER_AREA))
    return levels


# --- the scene -----------------------------------------------------------------------------------

@dataclass
class Quad:
    """A textured parallelogram: the texture's top-left corner at @p corner, its rows along @p edge_u
    (the texture's width) and its columns along @p edge_v (its height); world coordinates, metres.
    Every quad bounds a solid or the courtyard, so it is seen from one side only: the one @p front
    (a unit normal) points to."""
    name: str
    corner: np.ndarray
    edge_u: np.ndarray
    edge_v: np.ndarray
    front: np.ndarray
    levels: list

    def corners(self):
        c, u, v = self.corner, self.edge_u, self.edge_v
        return np.array([c, c + u, c + u + v, c + v])

    def faces(self, point):
        """Whether @p point is on the side the quad is seen from."""
        return float((point - self.corner) @ self.front) > 0.0


def quad(name, corner, edge_u, edge_v, front, texture):
    front = np.asarray(front, np.float64)
    return Quad(name, np.asarray(corner, np.float64), np.asarray(edge_u, np.float64),
                np.asarray(edge_v, np.float64), front / np.linalg.norm(front), mipmap(texture))


def texture_part(texture, u0, u1, v0, v1):
    """The part of @p texture between the fractions u0..u1 of its width and v0..v1 of its height,
    with the fractions moved onto its pixel boundaries (returned)."""
    h, w = texture.shape[:2]
    c0, c1, r0, r1 = round(u0 * w), round(u1 * w), round(v0 * h), round(v1 * h)
    return texture[r0:r1, c0:c1], (c0 / w, c1 / w, r0 / h, r1 / h)


def resized(texture, width_m, height_m):
    """@p texture resized to width_m x height_m at PX_PER_M."""
    size = (max(2, round(width_m * PX_PER_M)), max(2, round(height_m * PX_PER_M)))
    shrinking = size[0] * size[1] < texture.shape[0] * texture.shape[1]
    return cv2.resize(texture, size, interpolation=cv2.INTER_AREA if shrinking else cv2.INTER_CUBIC)


UP = np.array([0.0, 0.0, 1.0])


@dataclass
class Wall:
    """A wall's inner face: seen from inside the courtyard, its left end at @p origin on the ground,
    running along @p along for @p length; @p normal points into the courtyard."""
    origin: np.ndarray
    along: np.ndarray
    normal: np.ndarray
    length: float

    def point(self, s, z, depth=0.0):
        """The point @p s along the wall, @p z above the ground, @p depth behind its face."""
        return self.origin + s * self.along + z * UP - depth * self.normal


def wall_rectangle(name, wall, s0, s1, z0, z1, texture, depth=0.0):
    """The part s0..s1, z0..z1 of the wall's face (@p depth behind it) covered by @p texture."""
    return quad(name, wall.point(s0, z1, depth), (s1 - s0) * wall.along, -(z1 - z0) * UP, wall.normal, texture)


@dataclass
class Opening:
    """A door or window in a wall: from s0 to s1 along it, z0 to z1 high, its @p inner texture
    @p recess behind the wall's face, the recess's sides covered by @p reveal."""
    s0: float
    s1: float
    z0: float
    z1: float
    recess: float
    inner: np.ndarray
    reveal: np.ndarray


def facade(name, wall, s0, s1, z0, z1, texture, opening=None):
    """The wall's part s0..s1, z0..z1 covered by @p texture, with an optional Opening: the wall
    around it in up to four pieces of the texture, the recessed door or window, and the recess's
    four sides (the reveals: left, right, head and sill, or the floor of a door's recess)."""
    if opening is None:
        return [wall_rectangle(name, wall, s0, s1, z0, z1, texture)]
    width, height = s1 - s0, z1 - z0
    # The opening's edges on the texture's pixel boundaries, so that the pieces meet without a seam.
    _, (u0, u1, v0, v1) = texture_part(texture, (opening.s0 - s0) / width, (opening.s1 - s0) / width,
                                       (z1 - opening.z1) / height, (z1 - opening.z0) / height)
    os0, os1, oz1, oz0 = s0 + u0 * width, s0 + u1 * width, z1 - v0 * height, z1 - v1 * height
    pieces = []
    for part, (a, b, c, d) in (("left", (0.0, u0, 0.0, 1.0)), ("right", (u1, 1.0, 0.0, 1.0)),
                               ("above", (u0, u1, 0.0, v0)), ("below", (u0, u1, v1, 1.0))):
        if b > a and d > c:
            piece, _ = texture_part(texture, a, b, c, d)
            pieces.append(wall_rectangle(f"{name}/{part}", wall, s0 + a * width, s0 + b * width,
                                         z1 - d * height, z1 - c * height, piece))
    recess, open_w, open_h = opening.recess, os1 - os0, oz1 - oz0
    pieces.append(wall_rectangle(f"{name}/inner", wall, os0, os1, oz0, oz1, opening.inner, depth=recess))
    back = -recess * wall.normal
    side = resized(opening.reveal, recess, open_h)
    pieces.append(quad(f"{name}/reveal-left", wall.point(os0, oz1), back, -open_h * UP, wall.along, side))
    pieces.append(quad(f"{name}/reveal-right", wall.point(os1, oz1), back, -open_h * UP, -wall.along, side))
    flat = resized(opening.reveal, open_w, recess)
    pieces.append(quad(f"{name}/reveal-head", wall.point(os0, oz1), open_w * wall.along, back, -UP, flat))
    pieces.append(quad(f"{name}/reveal-sill", wall.point(os0, oz0), open_w * wall.along, back, UP, flat))
    return pieces


def box(name, x0, x1, y0, y1, z0, z1, front, side, top, front_normal):
    """A block standing on the ground (or on another block): its four sides and its top. The side
    facing @p front_normal ((+-1, 0) or (0, +-1)) is covered by @p front, the others by @p side, the
    top by @p top (textures resized to the faces)."""
    faces = []
    for nx, ny in ((1, 0), (-1, 0), (0, 1), (0, -1)):
        # Seen from outside, a face's left end: its texture starts there.
        if nx:
            x = x1 if nx > 0 else x0
            start, end = ((x, y0), (x, y1)) if nx > 0 else ((x, y1), (x, y0))
        else:
            y = y1 if ny > 0 else y0
            start, end = ((x1, y), (x0, y)) if ny > 0 else ((x0, y), (x1, y))
        start, end = np.array([*start, z1]), np.array([*end, z1])
        width = float(np.linalg.norm(end - start))
        is_front = (nx, ny) == tuple(front_normal)
        texture = resized(front if is_front else side, width, z1 - z0)
        faces.append(quad(f"{name}/{'front' if is_front else 'side'}({nx},{ny})", start, end - start,
                          -(z1 - z0) * UP, [nx, ny, 0], texture))
    faces.append(quad(f"{name}/top", [x0, y1, z1], [x1 - x0, 0, 0], [0, -(y1 - y0), 0], UP,
                      resized(top, x1 - x0, y1 - y0)))
    return faces


def walls():
    """The courtyard's four walls, seen from inside: south, north, east, west."""
    L, W = HALF_LENGTH, HALF_WIDTH
    return {
        "south": Wall(np.array([L, -W, 0.0]), np.array([-1.0, 0, 0]), np.array([0, 1.0, 0]), 2 * L),
        "north": Wall(np.array([-L, W, 0.0]), np.array([1.0, 0, 0]), np.array([0, -1.0, 0]), 2 * L),
        "east": Wall(np.array([L, W, 0.0]), np.array([0, -1.0, 0]), np.array([-1.0, 0, 0]), 2 * W),
        "west": Wall(np.array([-L, -W, 0.0]), np.array([0, 1.0, 0]), np.array([1.0, 0, 0]), 2 * W),
    }


GROUND_FLOOR = 3.2  # m: the height at which the buildings' upper storeys begin


def building(name, wall, s0, s1, lower, upper, opening=None, upper_opening=None):
    """One building front on @p wall from s0 to s1: a ground floor and an upper storey, each of the
    material (name, at, flip) @p lower / @p upper with an optional Opening."""
    lower_texture = material(lower[0], s1 - s0, GROUND_FLOOR, at=lower[1], flip=lower[2])
    upper_texture = material(upper[0], s1 - s0, WALL_HEIGHT - GROUND_FLOOR, at=upper[1], flip=upper[2])
    return (facade(f"{name}/ground-floor", wall, s0, s1, 0.0, GROUND_FLOOR, lower_texture, opening)
            + facade(f"{name}/upper", wall, s0, s1, GROUND_FLOOR, WALL_HEIGHT, upper_texture, upper_opening))


def door(name, centre, width, height, recess=0.25):
    """A door of material @p name, its middle @p centre along the wall, in a recess with stone sides."""
    return Opening(centre - width / 2, centre + width / 2, 0.0, height, recess, material(name, width, height),
                   material("plinth_a", 1.0, 0.4))


def window(name, centre, width, z0, height, recess=0.15, frame=0.05):
    """A window of material @p name with a dark frame of @p frame, in a recess with stone sides."""
    return Opening(centre - width / 2, centre + width / 2, z0, z0 + height, recess,
                   framed(material(name, width, height), frame), material("stone_c", 1.0, 0.5))


def steps(name, x_front, y0, y1, count, rise, run, wall_x):
    """@p count steps rising towards a wall at x = @p wall_x (+x), each a block from its front to the
    wall."""
    faces = []
    for i in range(count):
        front = x_front + i * run
        faces += box(f"{name}/{i}", front, wall_x, y0, y1, i * rise, (i + 1) * rise,
                     material("plinth_a", y1 - y0, rise, at=i / count), material("plinth_b", wall_x - front, rise),
                     material("cobbles_b", wall_x - front, y1 - y0, at=0.3 * i), front_normal=(-1, 0))
    return faces


def ground():
    """The ground: three cobbled bands along the courtyard, each in tiles of one texture (tiles keep
    the texture level chosen per quad close to what each part of the ground needs)."""
    L, W = HALF_LENGTH, HALF_WIDTH
    bands = ("cobbles_a", "cobbles_b", "cobbles_c")
    depth, tiles = 2 * W / len(bands), 5
    faces = []
    for b, name in enumerate(bands):
        texture = material(name, 2 * L, depth, at=0.5, flip=bool(b % 2))
        y_top = W - b * depth
        for k in range(tiles):
            part, (u0, u1, _, _) = texture_part(texture, k / tiles, (k + 1) / tiles, 0.0, 1.0)
            faces.append(quad(f"ground/{name}/{k}", [-L + u0 * 2 * L, y_top, 0.0], [(u1 - u0) * 2 * L, 0, 0],
                              [0, -depth, 0], UP, part))
    return faces


@lru_cache(maxsize=1)
def courtyard():
    """The scene's quads (a tuple of Quad), built once."""
    w = walls()
    south, north, east, west = w["south"], w["north"], w["east"], w["west"]
    faces = []
    # South wall (the walk passes it 2 m away): four buildings, materials as (name, at, flip).
    faces += building("south-1", south, 0.0, 2.8, ("brick_b", 0.0, False), ("arcade_a", 0, False),
                      window("window_b", 1.4, 1.3, 1.0, 1.3))
    faces += building("south-2", south, 2.8, 5.6, ("stone_b", 0.6, False), ("stone_a", 0.0, False),
                      door("door_a", 4.2, 1.6, 2.2), window("window_a", 4.2, 0.8, 3.8, 1.6))
    faces += building("south-3", south, 5.6, 8.3, ("plaster", 0.5, False), ("plaster", 0.0, True),
                      window("window_a", 6.95, 0.9, 0.9, 1.8))
    faces += building("south-4", south, 8.3, 11.0, ("brick_d", 0.3, False), ("stone_c", 0.0, True),
                      door("door_b", 9.6, 1.5, 2.3, recess=0.2))
    # North wall: four more.
    faces += building("north-1", north, 0.0, 3.0, ("stone_f", 0.8, False), ("arcade_b", 0, False),
                      window("window_a", 1.5, 0.9, 1.0, 1.8))
    faces += building("north-2", north, 3.0, 5.5, ("brick_c", 0.6, False), ("brick_c", 0.0, True),
                      door("door_c", 4.25, 1.6, 2.1, recess=0.3), window("window_b", 4.25, 1.2, 3.9, 1.2))
    faces += building("north-3", north, 5.5, 8.5, ("stone_a", 1.0, True), ("relief", 0, False),
                      window("window_b", 7.0, 1.2, 0.9, 1.2, recess=0.1))
    faces += building("north-4", north, 8.5, 11.0, ("brick_a", 0.7, False), ("arcade_a", 0, True),
                      door("door_a", 9.75, 1.5, 2.2))
    # East wall: a church portal standing out of a stone wall, with steps in front of it.
    faces += building("east-1", east, 0.0, 1.9, ("stone_d", 0.5, True), ("stone_f", 0.0, False))
    faces += building("east-2", east, 1.9, 4.5, ("stone_b", 0.1, False), ("relief", 0, False))
    faces += building("east-3", east, 4.5, 6.4, ("stone_d", 0.0, False), ("stone_c", 0.0, False))
    x_wall, portal_depth, stairs, rise, run = HALF_LENGTH, 0.25, 3, 0.15, 0.3
    faces += box("portal", x_wall - portal_depth, x_wall, -1.2, 1.2, stairs * rise, stairs * rise + 3.4,
                 material("portal", 2.4, 3.4), material("stone_c", portal_depth, 3.4),
                 material("stone_c", 2.4, portal_depth), front_normal=(-1, 0))
    faces += steps("steps", x_wall - portal_depth - stairs * run, -1.6, 1.6, stairs, rise, run, x_wall)
    # West wall: the fountain against brick.
    faces += building("west-1", west, 0.0, 1.5, ("brick_a", 0.2, True), ("brick_b", 0.9, True))
    faces += building("west-2", west, 1.5, 4.9, ("brick_d", 0.0, False), ("arcade_b", 0, True))
    faces += building("west-3", west, 4.9, 6.4, ("brick_a", 1.0, False), ("brick_c", 1.0, False))
    x_wall = -HALF_LENGTH
    faces += box("fountain", x_wall, x_wall + 0.35, -1.6, 1.6, 0.0, 2.9, material("fountain", 3.2, 2.9),
                 material("brick_b", 0.35, 2.9), material("plinth_a", 0.35, 3.2), front_normal=(1, 0))
    # Standing free: a pillar and a bench.
    faces += box("pillar", 3.4, 3.9, 1.7, 2.2, 0.0, 2.6, material("stone_b", 0.5, 2.6),
                 material("stone_d", 0.5, 2.6), material("plinth_b", 0.5, 0.5), front_normal=(-1, 0))
    faces += box("bench", -4.2, -2.6, -2.7, -2.2, 0.0, 0.45, material("plinth_a", 1.6, 0.45),
                 material("plinth_b", 0.5, 0.45), material("stone_c", 1.6, 0.5), front_normal=(0, 1))
    faces += ground()
    L, W = HALF_LENGTH, HALF_WIDTH
    faces.append(quad("sky", [-L, -W, WALL_HEIGHT], [2 * L, 0, 0], [0, 2 * W, 0], -UP, sky()))
    return tuple(faces)


# --- the walk ------------------------------------------------------------------------------------

def rotation_x(angle):
    c, s = math.cos(angle), math.sin(angle)
    return np.array([[1, 0, 0], [0, c, -s], [0, s, c]])


def rotation_z(angle):
    c, s = math.cos(angle), math.sin(angle)
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])


# The camera looking along +x, upright: its x axis (right) is -y, its y axis (down) is -z.
CAMERA_LOOKING_EAST = np.array([[0.0, 0.0, 1.0], [-1.0, 0.0, 0.0], [0.0, -1.0, 0.0]])


def walk_pose(frame):
    """The left camera's pose at @p frame (x_cam = R X + t, world to camera): on the ellipse WALK_A x
    WALK_B, heading along it, the head turning, nodding and rolling gently; periodic in LOOP_FRAMES,
    every term a whole number of cycles per loop, so that the walk is smooth and closes."""
    theta = 2.0 * math.pi * frame / LOOP_FRAMES
    centre = np.array([WALK_A * math.sin(theta), -WALK_B * math.cos(theta),
                       EYE_HEIGHT + 0.015 * math.sin(10 * theta)])
    heading = math.atan2(WALK_B * math.sin(theta), WALK_A * math.cos(theta))
    yaw = heading + math.radians(7.0) * math.sin(2 * theta + 0.3)
    pitch = math.radians(-2.0 + 2.5 * math.sin(3 * theta))
    roll = math.radians(1.5 * math.sin(4 * theta + 1.0))
    # Camera to world: turned by yaw about the vertical, then nodded about its x and rolled about its z.
    R_cw = rotation_z(yaw) @ CAMERA_LOOKING_EAST @ rotation_x(pitch) @ rotation_z(roll)
    R = R_cw.T
    return R, -R @ centre


def right_pose(R, t):
    """The right camera of the rig whose left camera is at (R, t): BASELINE along the left's x."""
    return R.copy(), t - np.array([BASELINE, 0.0, 0.0])


def rig():
    """(R12, t12): the right camera's pose in the left camera's frame."""
    return np.eye(3), np.array([-BASELINE, 0.0, 0.0])


def check_clearance(quads, poses, minimum=0.5):
    """ValueError naming the frame and quad when a camera centre comes closer than @p minimum (m)
    to a quad, or leaves the courtyard."""
    for frame, (R, t) in enumerate(poses):
        c = rs.camera_centre(R, t)
        if not (abs(c[0]) < HALF_LENGTH - minimum and abs(c[1]) < HALF_WIDTH - minimum
                and minimum < c[2] < WALL_HEIGHT - minimum):
            raise ValueError(f"frame {frame}: the camera at {c} is outside the courtyard")
        for q in quads:
            if _distance_to_quad(c, q) < minimum:
                raise ValueError(f"frame {frame}: the camera at {c} is within {minimum} m of {q.name}")


def _distance_to_quad(point, q):
    """The distance from @p point to the parallelogram @p q."""
    d = point - q.corner
    # Coordinates along the two edges (they are perpendicular in this scene), clamped to the quad.
    s = np.clip(d @ q.edge_u / (q.edge_u @ q.edge_u), 0.0, 1.0)
    r = np.clip(d @ q.edge_v / (q.edge_v @ q.edge_v), 0.0, 1.0)
    return float(np.linalg.norm(d - s * q.edge_u - r * q.edge_v))


# --- rendering -----------------------------------------------------------------------------------

def supersampled_camera(K_image, factor):
    """K of the image @p factor times larger whose pixel blocks average onto the image's pixels:
    pixel centres map as x' = factor x + (factor - 1) / 2."""
    S = np.array([[factor, 0.0, (factor - 1) / 2.0], [0.0, factor, (factor - 1) / 2.0], [0.0, 0.0, 1.0]])
    return S @ K_image


def _clip_near(points):
    """The polygon @p points (camera coordinates, in order) clipped to z >= NEAR."""
    out = []
    n = len(points)
    for i in range(n):
        a, b = points[i], points[(i + 1) % n]
        a_in, b_in = a[2] >= NEAR, b[2] >= NEAR
        if a_in:
            out.append(a)
        if a_in != b_in:
            out.append(a + (NEAR - a[2]) / (b[2] - a[2]) * (b - a))
    return np.array(out)


class Canvas:
    """One view being rendered: colour, inverse depth (0 where nothing is drawn yet) and the index of
    the quad seen at each sample."""

    def __init__(self, width, height):
        self.colour = np.zeros((height, width, 3), np.uint8)
        self.inverse_depth = np.zeros((height, width), np.float64)
        self.index = np.full((height, width), -1, np.int32)


# Quads sharing an edge both cover samples this close to it (relative), so that none falls between.
EDGE_TOLERANCE = 1e-9


def draw_quad(canvas, q, index, K_view, R, t):
    """Draws quad @p q into @p canvas where it is nearer than what is there.

    Its plane maps texture fractions (s, r, 1) to pixels by G = K [R e_u, R e_v, R c + t], whose
    last coordinate is the depth; so G^-1 x = (s, r, 1) / depth at the pixel x: the quad covers x
    where 0 <= s <= 1 and 0 <= r <= 1 in front of the camera (1/depth > 0), and is the nearest
    surface there where 1/depth, affine in x, is the largest drawn. Each of these conditions is a
    half-plane of pixels, so on each row the quad covers one interval."""
    centre = -R.T @ t
    if not q.faces(centre):
        return
    polygon = _clip_near(q.corners() @ R.T + t)
    if len(polygon) < 3:
        return
    pixels = polygon @ K_view.T
    pixels = pixels[:, :2] / pixels[:, 2:]
    height, width = canvas.inverse_depth.shape
    x0, y0 = max(0, int(math.floor(pixels[:, 0].min()))), max(0, int(math.floor(pixels[:, 1].min())))
    x1, y1 = min(width, int(math.ceil(pixels[:, 0].max())) + 1), min(height, int(math.ceil(pixels[:, 1].max())) + 1)
    if x1 <= x0 or y1 <= y0:
        return
    G = K_view @ np.column_stack([R @ q.edge_u, R @ q.edge_v, R @ q.corner + t])
    if abs(np.linalg.det(G)) < 1e-12 * np.abs(G).max() ** 3:
        return  # seen edge-on
    Ginv = np.linalg.inv(G)
    s, r, w = Ginv
    eps = EDGE_TOLERANCE
    half_planes = np.array([s + eps * w, (1 + eps) * w - s, r + eps * w, (1 + eps) * w - r, w])
    rows = np.arange(y0, y1, dtype=np.float64)
    first, last = _row_intervals(half_planes, rows, x0, x1 - 1)
    covered = np.nonzero(last >= first)[0]
    if len(covered) == 0:
        return
    y0, y1 = y0 + int(covered[0]), y0 + int(covered[-1]) + 1
    first, last = first[covered[0]:covered[-1] + 1], last[covered[0]:covered[-1] + 1]
    x0, x1 = int(first.min()), int(last.max()) + 1
    columns = np.arange(x0, x1, dtype=np.float64)
    inverse_depth = w[0] * columns[None, :] + (w[1] * np.arange(y0, y1) + w[2])[:, None]
    target = canvas.inverse_depth[y0:y1, x0:x1]
    nearer = ((columns[None, :] >= first[:, None]) & (columns[None, :] <= last[:, None])
              & (inverse_depth > target))
    if not nearer.any():
        return
    texture = q.levels[_mip_level(q, Ginv, pixels)]
    th, tw = texture.shape[:2]
    # A pixel of the box (its origin at x0, y0) to a texture pixel: centres at (s w - 0.5, r h - 0.5).
    to_texture = np.array([[tw, 0, -0.5], [0, th, -0.5], [0, 0, 1]]) @ Ginv @ np.array(
        [[1, 0, x0], [0, 1, y0], [0, 0, 1]], np.float64)
    warped = cv2.warpPerspective(texture, to_texture, (x1 - x0, y1 - y0),
                                 flags=cv2.INTER_LINEAR | cv2.WARP_INVERSE_MAP, borderMode=cv2.BORDER_REPLICATE)
    np.copyto(canvas.colour[y0:y1, x0:x1], warped, where=nearer[:, :, None])
    np.copyto(target, inverse_depth, where=nearer)
    canvas.index[y0:y1, x0:x1][nearer] = index


def _row_intervals(half_planes, rows, lowest, highest):
    """Per row v of @p rows, the first and last whole column u in lowest..highest with
    a u + b v + c >= 0 for every (a, b, c) of @p half_planes (last < first: none)."""
    first = np.full(len(rows), float(lowest))
    last = np.full(len(rows), float(highest))
    for a, b, c in half_planes:
        k = b * rows + c
        if a > 0:
            first = np.maximum(first, np.ceil(-k / a))
        elif a < 0:
            last = np.minimum(last, np.floor(-k / a))
        else:
            last = np.where(k >= 0, last, -np.inf)
    return first, last


def _mip_level(q, Ginv, pixels):
    """The texture level whose pixels are about as large as the view's where the quad is least
    reduced: the area ratio of texture to view pixels at a point x is |det A| / (A x)_3^3 for the
    homography A from view to texture."""
    h, w = q.levels[0].shape[:2]
    A = np.array([[w, 0, -0.5], [0, h, -0.5], [0, 0, 1]]) @ Ginv
    third = np.column_stack([pixels, np.ones(len(pixels))]) @ A[2]
    area = abs(np.linalg.det(A)) / np.abs(third) ** 3
    reduction = math.sqrt(float(area.min()))
    return int(np.clip(math.floor(math.log2(max(reduction, 1.0))), 0, len(q.levels) - 1))


def render_view(quads, R, t, K_image=K, size=(WIDTH, HEIGHT), factor=SUPERSAMPLE):
    """The view of the camera (R, t) as (colour image float32 at @p size, Canvas at @p factor times
    the size). ValueError when a sample sees no quad (a gap in the scene)."""
    canvas = Canvas(size[0] * factor, size[1] * factor)
    K_view = supersampled_camera(K_image, factor)
    for index, q in enumerate(quads):
        draw_quad(canvas, q, index, K_view, R, t)
    if (canvas.index < 0).any():
        raise ValueError(f"{int((canvas.index < 0).sum())} samples of the view see no quad")
    image = cv2.resize(canvas.colour.astype(np.float32), size, interpolation=cv2.INTER_AREA)
    return image, canvas


def sensor_image(image, noise, seed, frame, camera):
    """@p image as 8 bits with Gaussian noise of @p noise grey levels, drawn from a generator seeded
    by (seed, frame, camera): every frame reproducible on its own."""
    if noise > 0:
        rng = np.random.default_rng([seed, frame, camera])
        image = image + rng.normal(0.0, noise, image.shape).astype(np.float32)
    return np.clip(np.rint(image), 0, 255).astype(np.uint8)


# --- the written sequence ------------------------------------------------------------------------

def poses(frames):
    """The left camera's poses of frames 0..frames-1, world to camera."""
    return [walk_pose(k) for k in range(frames)]


def relative_to_frame0(poses_world):
    """The poses with the world moved to frame 0's camera, as the trackers' world is."""
    R0, t0 = poses_world[0]
    return [rs.relative_pose(R0, t0, R, t) for R, t in poses_world]


def write_calibration(folder, poses_world, stereo):
    """calib.yml (and, for a rig, calib_mono.yml) as tripose_track --calib reads them."""
    dist = np.zeros(5)
    first = relative_to_frame0(poses_world[:2])
    mono = {"R12": first[1][0], "t12": first[1][1]}
    if stereo:
        R12, t12 = rig()
        rs.write_calibration_yaml(folder / "calib.yml", K, dist, R12=R12, t12=t12)
        rs.write_calibration_yaml(folder / "calib_mono.yml", K, dist, **mono)
    else:
        rs.write_calibration_yaml(folder / "calib.yml", K, dist, **mono)


def write_sequence(folder, frames=LOOP_FRAMES, stereo=False, seed=0, noise=NOISE, progress=None):
    """Renders @p frames frames into @p folder (the layout of the module's description); returns the
    seconds spent rendering."""
    if frames < 2:
        raise ValueError(f"frames: at least 2 are needed (the mono calibration holds frames 0-1), got {frames}")
    if noise < 0:
        raise ValueError(f"noise: expected a standard deviation >= 0, got {noise}")
    if seed < 0:
        raise ValueError(f"seed: expected a whole number >= 0, got {seed}")
    folder = Path(folder)
    quads = courtyard()
    walk = poses(frames)
    check_clearance(quads, walk + ([right_pose(R, t) for R, t in walk] if stereo else []))
    cameras = [("left", lambda R, t: (R, t))] + ([("right", right_pose)] if stereo else [])
    for name, _ in cameras:
        (folder / name).mkdir(parents=True, exist_ok=True)
    stamps = [k / FPS for k in range(frames)]
    start = time.perf_counter()
    for k, (R, t) in enumerate(walk):
        for camera, (name, pose_of) in enumerate(cameras):
            image, _ = render_view(quads, *pose_of(R, t))
            cv2.imwrite(str(folder / name / f"{k:06d}.png"), sensor_image(image, noise, seed, k, camera))
        if progress:
            progress(k)
    seconds = time.perf_counter() - start
    for name, _ in cameras:
        (folder / f"{name}.txt").write_text("".join(f"{s:.9f} {name}/{k:06d}.png\n" for k, s in enumerate(stamps)))
    write_calibration(folder, walk, stereo)
    relative = relative_to_frame0(walk)
    rs.write_tum(folder / "groundtruth.txt", stamps, [p[0] for p in relative], [p[1] for p in relative])
    return seconds


def contact_sheet(folder, frames, path, columns=4, camera="left"):
    """The frames @p frames of a written sequence side by side in one image at @p path, each labelled."""
    tiles = []
    for k in frames:
        image = cv2.imread(str(Path(folder) / camera / f"{k:06d}.png"), cv2.IMREAD_COLOR)
        cv2.putText(image, f"{camera} {k}", (8, 24), cv2.FONT_HERSHEY_SIMPLEX, 0.7, (0, 255, 255), 2)
        tiles.append(image)
    while len(tiles) % columns:
        tiles.append(np.zeros_like(tiles[0]))
    rows = [np.hstack(tiles[i:i + columns]) for i in range(0, len(tiles), columns)]
    cv2.imwrite(str(path), np.vstack(rows))


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--output", required=True, type=Path, help="the folder written")
    parser.add_argument("--frames", type=int, default=LOOP_FRAMES,
                        help=f"frames rendered from the start (default {LOOP_FRAMES}, one loop)")
    parser.add_argument("--stereo", action="store_true", help=f"also the right camera, {BASELINE} m to the right")
    parser.add_argument("--seed", type=int, default=0, help="seed of the sensor noise")
    parser.add_argument("--noise", type=float, default=NOISE, help=f"sensor noise, grey levels (default {NOISE})")
    parser.add_argument("--contact-sheet", type=Path, help="also write a few frames side by side to this PNG")
    args = parser.parse_args(argv)
    seconds = write_sequence(args.output, args.frames, args.stereo, args.seed, args.noise)
    views = args.frames * (2 if args.stereo else 1)
    print(f"{args.frames} frames{' (stereo)' if args.stereo else ''} written to {args.output} in {seconds:.1f} s "
          f"({1000 * seconds / views:.0f} ms per view)")
    if args.contact_sheet:
        picks = np.linspace(0, args.frames - 1, 8).round().astype(int)
        contact_sheet(args.output, picks, args.contact_sheet)


if __name__ == "__main__":
    main()
