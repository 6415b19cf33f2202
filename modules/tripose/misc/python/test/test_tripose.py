#!/usr/bin/env python
"""Python bindings of the tripose module: synthetic three-view scenes, made here in numpy (the scene
generator of the C++ tests is no part of the module), solved through cv2.tripose.

Run inside an OpenCV build (scripts/test_intree.sh does it):
  OPENCV_PYTEST_FILTER=test_tripose python3 <opencv>/modules/python/test/test.py --repo <opencv>
"""

from __future__ import print_function

import re

import numpy as np
import cv2 as cv

from tests_common import NewOpenCVTests


def rotation_error(R, R_true):
    """Angle (radians) of the rotation R R_true^T. atan2 of its sine (skew part) and cosine (trace)
    stays accurate near zero, where arccos of the trace alone cannot resolve less than ~1e-8 rad."""
    M = np.asarray(R, dtype=np.float64) @ np.asarray(R_true, dtype=np.float64).T
    sin = 0.5 * np.linalg.norm([M[2, 1] - M[1, 2], M[0, 2] - M[2, 0], M[1, 0] - M[0, 1]])
    cos = 0.5 * (np.trace(M) - 1.0)
    return np.arctan2(sin, cos)


def translation_error(t, t_true):
    """||t - t_true|| / ||t_true||: t carries the metric scale of t12, so its length counts too."""
    t, t_true = np.asarray(t).ravel(), np.asarray(t_true).ravel()
    return np.linalg.norm(t - t_true) / np.linalg.norm(t_true)


class Scene(object):
    """A three-view scene with its ground truth, all in the frame of view 1: x ~ K (R X + t)."""


def look_at_origin(centre, roll):
    """World-to-camera rotation of a camera at `centre` looking at the origin, rolled by `roll`."""
    z = -centre / np.linalg.norm(centre)
    helper = np.array([1.0, 0, 0]) if abs(z[0]) < 0.9 else np.array([0, 1.0, 0])
    x0 = np.cross(helper, z)
    x0 /= np.linalg.norm(x0)
    y0 = np.cross(z, x0)
    x = np.cos(roll) * x0 + np.sin(roll) * y0
    return np.array([x, np.cross(z, x), z])


def project(K, R, t, X):
    """Pixels (Nx2) and depths (N) of the points X (Nx3) in the camera K [R | t]."""
    c = X @ R.T + t.ravel()
    p = c @ K.T
    return p[:, :2] / p[:, 2:], c[:, 2]


def sample(n, draw, keep):
    """n rows of draw(batch) that keep() accepts (the scene generators' rejection sampling)."""
    rows = [draw(0)[:0]]
    for _ in range(1000):
        if sum(len(r) for r in rows) >= n:
            break
        candidates = draw(max(64, 4 * n))
        rows.append(candidates[keep(candidates)])
    rows = np.concatenate(rows)
    assert len(rows) >= n, 'the scene generator found too few visible features'
    return rows[:n]


def make_scene(num_points, num_lines, seed, noise=0.0, outliers=0.0, K=None, image_size=(640, 480)):
    """The synthetic protocol of the paper (Qadir & Neubert, Sec. IV-A) in numpy: points and segment
    end points uniform in a 10 m cube at the origin, three cameras (f = 800 px unless K is given) at
    20 m in random directions looking at it. Every feature projects at least 2 px inside all three
    images, in front of the cameras, and every segment is at least 20 px long in each; then Gaussian
    noise of `noise` px on every coordinate. A fraction `outliers` of the points and of the lines get
    a random view-3 observation at least 20 px from the true one (pointInliers / lineInliers say which)."""
    rng = np.random.default_rng(seed)
    width, height = image_size
    if K is None:
        K = np.array([[800.0, 0, (width - 1) / 2.0], [0, 800.0, (height - 1) / 2.0], [0, 0, 1]])
    K = np.asarray(K, dtype=np.float64)
    margin, min_length, outlier_offset = 2.0, 20.0, 20.0

    # Cameras in the world frame, then everything in the frame of view 1.
    directions = rng.normal(size=(3, 3))
    centres = 20.0 * directions / np.linalg.norm(directions, axis=1, keepdims=True)
    Rw = [look_at_origin(c, rng.uniform(0, 2 * np.pi)) for c in centres]
    tw = [-R @ c for R, c in zip(Rw, centres)]
    poses = [(np.eye(3), np.zeros((3, 1)))] + [(R @ Rw[0].T, (t - R @ Rw[0].T @ tw[0]).reshape(3, 1))
                                                for R, t in zip(Rw[1:], tw[1:])]

    def random_structure(n):
        return rng.uniform(-5.0, 5.0, size=(n, 3)) @ Rw[0].T + tw[0]

    def visible(X):
        ok = np.ones(len(X), dtype=bool)
        for R, t in poses:
            x, depth = project(K, R, t, X)
            ok &= (depth > 0) & np.all((x >= margin) & (x <= np.array([width, height]) - 1 - margin), axis=1)
        return ok

    def long_segments(S):
        ok = visible(S[:, :3]) & visible(S[:, 3:])
        for R, t in poses:
            a, b = project(K, R, t, S[:, :3])[0], project(K, R, t, S[:, 3:])[0]
            ok &= np.linalg.norm(b - a, axis=1) >= min_length
        return ok

    scene = Scene()
    scene.points3d = sample(num_points, random_structure, visible)
    scene.lines3d = sample(num_lines, lambda n: np.hstack([random_structure(n), random_structure(n)]), long_segments)
    points = [project(K, R, t, scene.points3d)[0] for R, t in poses]
    lines = [np.hstack([project(K, R, t, scene.lines3d[:, :3])[0], project(K, R, t, scene.lines3d[:, 3:])[0]])
             for R, t in poses]

    def random_pixels(n):
        return rng.uniform([margin, margin], [width - 1 - margin, height - 1 - margin], size=(n, 2))

    scene.pointInliers = np.ones((num_points, 1), dtype=np.uint8)
    for i in rng.permutation(num_points)[:int(round(outliers * num_points))]:
        scene.pointInliers[i] = 0
        points[2][i] = sample(1, random_pixels, lambda x: np.linalg.norm(x - points[2][i], axis=1) >= outlier_offset)[0]
    scene.lineInliers = np.ones((num_lines, 1), dtype=np.uint8)
    for i in rng.permutation(num_lines)[:int(round(outliers * num_lines))]:
        scene.lineInliers[i] = 0
        a, b = lines[2][i, :2], lines[2][i, 2:]
        normal = np.array([a[1] - b[1], b[0] - a[0]]) / np.linalg.norm(b - a)

        def wrong(S):
            far = np.maximum(abs((S[:, :2] - a) @ normal), abs((S[:, 2:] - a) @ normal)) >= outlier_offset
            return far & (np.linalg.norm(S[:, 2:] - S[:, :2], axis=1) >= min_length)
        lines[2][i] = sample(1, lambda n: np.hstack([random_pixels(n), random_pixels(n)]), wrong)[0]

    if noise > 0:
        points = [x + rng.normal(0, noise, x.shape) for x in points]
        lines = [s + rng.normal(0, noise, s.shape) for s in lines]
    scene.points1, scene.points2, scene.points3 = points
    scene.lines1, scene.lines2, scene.lines3 = lines
    scene.cameraMatrices = [K.copy(), K.copy(), K.copy()]
    (_, _), (scene.R12, scene.t12), (scene.R, scene.t) = poses
    return scene


def axis_angle(rng, max_radians):
    """A rotation by an angle uniform in [0, max_radians] about a uniformly random axis."""
    axis = rng.normal(size=3)
    axis *= rng.uniform(0, max_radians) / np.linalg.norm(axis)
    return cv.Rodrigues(axis.reshape(3, 1))[0]


SEEN_IN_VIEW3, SEEN_IN_VIEW4, SEEN_IN_BOTH = 1, 2, 3


def make_rig_scene(num_points, num_lines, seed, noise=0.0, outliers=0.0, missing=0.0, visibility=None):
    """A stereo rig moving between two times, in numpy (the geometry of the C++ tests' rig scenes):
    view 1 = left camera at time A [I|0], view 2 = right camera at time A [R12|t12] (baseline
    0.1-0.5 m along x, turned up to 3 degrees), view 3 = left camera at time B [R|t] (moved 0.3-3 m,
    turned up to 20 degrees), view 4 = [R12 R | R12 t + t12]; f = 800 px, 640x480. Points: a pixel of
    view 1 at a depth of 5-30 m, at least 2 px inside all four images and 1 m in front; segments:
    two such points 0.5 m apart, at least 20 px long in every view. A fraction `outliers` of the
    points and of the lines get the time-B observations of another random point or segment (at
    least 20 px from the true ones); `visibility` (one of SEEN_IN_* per feature, points then lines)
    or a fraction `missing` of features seen by one time-B view only: NaN rows in the other."""
    rng = np.random.default_rng(seed)
    width, height, margin = 640, 480, 2.0
    K = np.array([[800.0, 0, (width - 1) / 2.0], [0, 800.0, (height - 1) / 2.0], [0, 0, 1]])
    centre2 = rng.uniform(0.1, 0.5) * np.array([1.0, 0.05 * rng.normal(), 0.05 * rng.normal()])
    R12 = axis_angle(rng, np.radians(3.0))
    t12 = (-R12 @ centre2).reshape(3, 1)
    direction = rng.normal(size=3)
    centre3 = rng.uniform(0.3, 3.0) * direction / np.linalg.norm(direction)
    R = axis_angle(rng, np.radians(20.0))
    t = (-R @ centre3).reshape(3, 1)
    poses = [(np.eye(3), np.zeros((3, 1))), (R12, t12), (R, t), (R12 @ R, R12 @ t + t12)]

    def visible(X):
        ok = np.ones(len(X), dtype=bool)
        for Rv, tv in poses:
            x, depth = project(K, Rv, tv, X)
            ok &= (depth > 1.0) & np.all((x >= margin) & (x <= np.array([width, height]) - 1 - margin), axis=1)
        return ok

    def draw_points(n):
        pixels = rng.uniform([margin, margin], [width - 1 - margin, height - 1 - margin], size=(n, 2))
        rays = np.hstack([(pixels - K[:2, 2]) / 800.0, np.ones((n, 1))])
        return rays * rng.uniform(5.0, 30.0, size=(n, 1))

    def long_segments(S):
        ok = visible(S[:, :3]) & visible(S[:, 3:]) & (np.linalg.norm(S[:, 3:] - S[:, :3], axis=1) >= 0.5)
        for Rv, tv in poses:
            ok &= np.linalg.norm(project(K, Rv, tv, S[:, 3:])[0] - project(K, Rv, tv, S[:, :3])[0], axis=1) >= 20.0
        return ok

    draw_segments = lambda n: np.hstack([draw_points(n), draw_points(n)])
    scene = Scene()
    scene.points3d = sample(num_points, draw_points, visible)
    scene.lines3d = sample(num_lines, draw_segments, long_segments)
    points = [project(K, Rv, tv, scene.points3d)[0] for Rv, tv in poses]
    lines = [np.hstack([project(K, Rv, tv, scene.lines3d[:, :3])[0], project(K, Rv, tv, scene.lines3d[:, 3:])[0]])
             for Rv, tv in poses]

    scene.pointInliers = np.ones((num_points, 1), dtype=np.uint8)
    for i in rng.permutation(num_points)[:int(round(outliers * num_points))]:
        scene.pointInliers[i] = 0
        far = lambda X: visible(X) & np.all([np.linalg.norm(project(K, Rv, tv, X)[0] - points[v][i], axis=1) >= 20.0
                                             for v, (Rv, tv) in enumerate(poses) if v >= 2], axis=0)
        X = sample(1, draw_points, far)
        for v in (2, 3):
            points[v][i] = project(K, poses[v][0], poses[v][1], X)[0][0]
    scene.lineInliers = np.ones((num_lines, 1), dtype=np.uint8)
    for i in rng.permutation(num_lines)[:int(round(outliers * num_lines))]:
        scene.lineInliers[i] = 0

        def far(S, i=i):
            ok = long_segments(S)
            for v in (2, 3):
                a, b = lines[v][i, :2], lines[v][i, 2:]
                normal = np.array([a[1] - b[1], b[0] - a[0]]) / np.linalg.norm(b - a)
                ends = [project(K, poses[v][0], poses[v][1], S[:, k:k + 3])[0] for k in (0, 3)]
                ok &= np.maximum(abs((ends[0] - a) @ normal), abs((ends[1] - a) @ normal)) >= 20.0
            return ok
        S = sample(1, draw_segments, far)
        for v in (2, 3):
            lines[v][i] = np.hstack([project(K, poses[v][0], poses[v][1], S[:, k:k + 3])[0][0] for k in (0, 3)])

    if noise > 0:
        points = [x + rng.normal(0, noise, x.shape) for x in points]
        lines = [x + rng.normal(0, noise, x.shape) for x in lines]
    if visibility is None:
        visibility = np.full(num_points + num_lines, SEEN_IN_BOTH)
        for kind, count in ((0, num_points), (num_points, num_lines)):
            chosen = kind + rng.permutation(count)[:int(round(missing * count))]
            visibility[chosen] = rng.choice([SEEN_IN_VIEW3, SEEN_IN_VIEW4], size=len(chosen))
    visibility = np.asarray(visibility)
    scene.pointVisibility, scene.lineVisibility = visibility[:num_points], visibility[num_points:]
    for v, bit in ((2, SEEN_IN_VIEW3), (3, SEEN_IN_VIEW4)):
        points[v][(scene.pointVisibility & bit) == 0] = np.nan
        lines[v][(scene.lineVisibility & bit) == 0] = np.nan
    scene.points1, scene.points2, scene.points3, scene.points4 = points
    scene.lines1, scene.lines2, scene.lines3, scene.lines4 = lines
    scene.cameraMatrices = [K.copy() for _ in range(4)]
    scene.R12, scene.t12, scene.R, scene.t = R12, t12, R, t
    scene.poses = poses
    return scene


def make_multiview_scene(num_known, num_points, num_lines, seed, outliers=0.0):
    """Several known views and a new one around a 10 m cube (cameras about 20 m away, f = 800 px, world
    frame the cube's), noise-free. Every feature is seen by the new view and a random subset of at
    least two known views; a row of NaN where a view does not see it. A fraction `outliers` of the
    points get a new-view observation far from the true one."""
    rng = np.random.default_rng(seed)
    K = np.array([[800.0, 0, 320], [0, 800.0, 240], [0, 0, 1]])
    views = num_known + 1
    Rs, ts = [], []
    for _ in range(views):
        direction = rng.normal(size=3)
        centre = 20.0 * direction / np.linalg.norm(direction)
        R = look_at_origin(centre, rng.uniform(0, 2 * np.pi))
        Rs.append(R)
        ts.append((-R @ centre).reshape(3, 1))
    scene = Scene()
    scene.K, scene.Rs, scene.ts = K, Rs[:num_known], ts[:num_known]
    scene.R, scene.t = Rs[num_known], ts[num_known]
    points3d = rng.uniform(-5.0, 5.0, size=(num_points, 3))
    ends = rng.uniform(-5.0, 5.0, size=(num_lines, 6))
    scene.points = [np.full((num_points, 2), np.nan) for _ in range(views)]
    scene.lines = [np.full((num_lines, 4), np.nan) for _ in range(views)]
    for kind, rows in ((0, num_points), (1, num_lines)):
        for i in range(rows):
            seen = list(rng.permutation(num_known)[:rng.integers(2, num_known + 1)]) + [num_known]
            for v in seen:
                if kind == 0:
                    scene.points[v][i] = project(K, Rs[v], ts[v], points3d[i:i + 1])[0][0]
                else:
                    scene.lines[v][i] = np.hstack([project(K, Rs[v], ts[v], ends[i:i + 1, :3])[0][0],
                                                   project(K, Rs[v], ts[v], ends[i:i + 1, 3:])[0][0]])
    scene.pointInliers = np.ones(num_points, dtype=np.uint8)
    for i in rng.permutation(num_points)[:int(round(outliers * num_points))]:
        scene.pointInliers[i] = 0
        scene.points[num_known][i] += rng.choice([-1, 1], size=2) * rng.uniform(30, 80, size=2)
    return scene


def rig_args(scene, **changes):
    """The arguments of the stereo functions for a rig scene, with `changes` applied."""
    args = dict(points1=scene.points1, points2=scene.points2, points3=scene.points3, points4=scene.points4,
                lines1=scene.lines1, lines2=scene.lines2, lines3=scene.lines3, lines4=scene.lines4,
                cameraMatrix=scene.cameraMatrices, distCoeffs=None, R12=scene.R12, t12=scene.t12)
    args.update(changes)
    return args


def params_without_floor():
    """RansacParams with no floor on the inliers (minInliers 0): for small problems whose features
    are all right."""
    params = cv.tripose.RansacParams()
    params.minInliers = 0
    return params


def names_argument(message, argument):
    """True when `message` names `argument` as a whole word ('R' is not named by 'R12')."""
    return re.search(r'(?<![\w.])' + re.escape(argument) + r'(?!\w)', message) is not None


def solve(scene, cameraMatrix=None, distCoeffs=None):
    """estimatePoseLinePoint on a scene; returns (count, R, t, Rs, ts, errors) (not the trailing
    covariance and noiseVariance, empty with POSE_LINEAR)."""
    K = scene.cameraMatrices if cameraMatrix is None else cameraMatrix
    return cv.tripose.estimatePoseLinePoint(
        scene.points1, scene.points2, scene.points3,
        scene.lines1, scene.lines2, scene.lines3,
        K, distCoeffs, scene.R12, scene.t12)[:6]


# Noise-free data: far above double-precision round-off through the SVD of the stacked system (the
# observed errors are below 1e-12), far below any real error. Same bounds as the C++ tests.
EXACT_ROTATION_RAD = 1e-6
EXACT_TRANSLATION = 1e-6


class tripose_test(NewOpenCVTests):

    def check_pose(self, R, t, scene, rot_tol, trans_tol, what):
        self.assertEqual(np.asarray(R).shape, (3, 3), what)
        self.assertEqual(np.asarray(t).size, 3, what)
        rot = rotation_error(R, scene.R)
        trans = translation_error(t, scene.t)
        self.assertLess(rot, rot_tol, '%s: rotation error %.3g rad' % (what, rot))
        self.assertLess(trans, trans_tol, '%s: relative translation error %.3g' % (what, trans))
        return rot, trans

    def test_scene_helper(self):
        # The scenes of these tests are exact: shapes, proper rotations, and noise-free points and
        # segment end points that project where they are observed, in every view.
        scene = make_scene(7, 5, seed=3)
        self.assertEqual(scene.points1.shape, (7, 2))
        self.assertEqual(scene.lines3.shape, (5, 4))
        self.assertEqual(len(scene.cameraMatrices), 3)
        for R in (scene.R12, scene.R):
            np.testing.assert_allclose(R @ R.T, np.eye(3), atol=1e-12)
            self.assertAlmostEqual(np.linalg.det(R), 1.0, places=12)
        views = [(np.eye(3), np.zeros((3, 1)), scene.points1, scene.lines1),
                 (scene.R12, scene.t12, scene.points2, scene.lines2), (scene.R, scene.t, scene.points3, scene.lines3)]
        for K, (R, t, points, lines) in zip(scene.cameraMatrices, views):
            np.testing.assert_allclose(project(K, R, t, scene.points3d)[0], points, atol=1e-9)
            np.testing.assert_allclose(project(K, R, t, scene.lines3d[:, :3])[0], lines[:, :2], atol=1e-9)
            np.testing.assert_allclose(project(K, R, t, scene.lines3d[:, 3:])[0], lines[:, 2:], atol=1e-9)

    def test_parameters_round_trip(self):
        # The members of the CV_EXPORTS_W_SIMPLE parameter structs: defaults seen from Python, values
        # set from Python read back.
        ransac = cv.tripose.RansacParams()
        self.assertEqual((ransac.threshold, ransac.confidence, ransac.maxIterations, ransac.localOptimization,
                          ransac.refine, ransac.seed, ransac.minInliers), (2.0, 0.999, 10000, True, True, 0, 15))
        ransac.threshold, ransac.confidence, ransac.maxIterations = 1.5, 0.99, 500
        ransac.localOptimization, ransac.refine, ransac.seed, ransac.minInliers = False, False, -7, 4
        self.assertEqual((ransac.threshold, ransac.confidence, ransac.maxIterations, ransac.localOptimization,
                          ransac.refine, ransac.seed, ransac.minInliers), (1.5, 0.99, 500, False, False, -7, 4))
        refine = cv.tripose.RefineParams()
        self.assertEqual((refine.maxIterations, refine.loss, refine.lossScale, refine.tolerance),
                         (30, cv.tripose.LOSS_SQUARED, 1.0, 1e-10))
        refine.maxIterations, refine.loss, refine.lossScale, refine.tolerance = 5, cv.tripose.LOSS_CAUCHY, 2.5, 1e-6
        self.assertEqual((refine.maxIterations, refine.loss, refine.lossScale, refine.tolerance),
                         (5, cv.tripose.LOSS_CAUCHY, 2.5, 1e-6))

    def test_non_default_intrinsics(self):
        # A camera other than the default one, given from Python as one shared matrix or a list of one.
        K = np.array([[500.0, 0, 300], [0, 520.0, 250], [0, 0, 1]])
        scene = make_scene(6, 2, seed=4, K=K, image_size=(600, 500))
        self.assertTrue(np.all((scene.points3 >= -0.5) & (scene.points3 < np.array([600, 500]) - 0.5)))
        for form, Kv in [('3x3 array', K), ('list of one K', [K])]:
            count, R, t = solve(scene, Kv)[:3]
            self.assertGreaterEqual(count, 1, form)
            self.check_pose(R, t, scene, EXACT_ROTATION_RAD, EXACT_TRANSLATION, form)

    def test_noise_free_overdetermined(self):
        # Six or more features: the best candidate is the exact pose.
        for num_points, num_lines in [(10, 0), (0, 10), (6, 6), (3, 3), (40, 40)]:
            for seed in range(3):
                scene = make_scene(num_points, num_lines, seed)
                what = '%d points, %d lines, seed %d' % (num_points, num_lines, seed)
                count, R, t, Rs, ts, errors = solve(scene)
                self.assertGreaterEqual(count, 1, what)
                self.assertEqual(len(Rs), count, what)
                self.assertEqual(len(ts), count, what)
                self.assertEqual(np.asarray(errors).size, count, what)
                self.check_pose(R, t, scene, EXACT_ROTATION_RAD, EXACT_TRANSLATION, what)
                self.assertLess(float(np.asarray(errors).ravel()[0]), 1e-6, what)

    def test_noise_free_minimal(self):
        # Four or five features: several poses can explain the data, so the true one must be among
        # the candidates (not necessarily ranked first).
        for num_points, num_lines in [(4, 0), (0, 4), (2, 2), (3, 1), (1, 3), (3, 2)]:
            for seed in range(3):
                scene = make_scene(num_points, num_lines, seed)
                what = '%d points, %d lines, seed %d' % (num_points, num_lines, seed)
                count, R, t, Rs, ts, errors = solve(scene)
                self.assertGreaterEqual(count, 1, what)
                found = any(rotation_error(Ri, scene.R) < EXACT_ROTATION_RAD and
                            translation_error(ti, scene.t) < EXACT_TRANSLATION
                            for Ri, ti in zip(Rs, ts))
                self.assertTrue(found, '%s: the true pose is not among the %d candidates' % (what, count))

    def test_mild_noise(self):
        # 0.5 px noise, 30 points and 30 lines, the paper's large-motion protocol. This checks that
        # Python callers get the solver's answer; the C++ tests cover its accuracy. Over 200 such
        # scenes the medians were 0.09 deg and 0.13 %, and 0.08-0.12 deg / 0.10-0.18 % over blocks of
        # 20: the bounds leave a factor 2.5, while a binding mistake (a transposed R, swapped views)
        # is off by degrees.
        rots, transs = [], []
        for seed in range(20):
            scene = make_scene(30, 30, seed, noise=0.5)
            count, R, t = solve(scene)[:3]
            self.assertGreaterEqual(count, 1, 'seed %d: no pose' % seed)
            rots.append(np.degrees(rotation_error(R, scene.R)))
            transs.append(translation_error(t, scene.t))
        print('\n0.5 px, 30 points + 30 lines, 20 scenes: median rotation error %.3g deg, median '
              'relative translation error %.3g' % (np.median(rots), np.median(transs)))
        self.assertLess(np.median(rots), 0.3)
        self.assertLess(np.median(transs), 0.005)

    def test_camera_matrix_as_lists(self):
        # cameraMatrix / distCoeffs are InputArrayOfArrays: one entry shared by the views or three.
        scene = make_scene(8, 8, seed=11)
        K = np.asarray(scene.cameraMatrices[0])
        for other in scene.cameraMatrices[1:]:
            np.testing.assert_array_equal(other, K)   # the default scene shares one K
        reference = solve(scene, [K, K, K])
        self.check_pose(reference[1], reference[2], scene, EXACT_ROTATION_RAD, EXACT_TRANSLATION, 'three K')
        zero = np.zeros(5)
        for form, Kv, dv in [('list of one K', [K], None), ('tuple of three K', (K, K, K), None),
                             ('zero distortion, one', [K], [zero]),
                             ('zero distortion, three', [K], [zero, zero, zero])]:
            count, R, t = solve(scene, Kv, dv)[:3]
            self.assertEqual(count, reference[0], form)
            np.testing.assert_allclose(R, reference[1], atol=1e-12, err_msg=form)
            np.testing.assert_allclose(t, reference[2], atol=1e-12, err_msg=form)

    def test_camera_matrix_as_single_array(self):
        # The natural call for one shared camera: K as a 3x3 array and distortion as a flat array,
        # as cv.solvePnP takes them. An InputArrayOfArrays binding splits an array into its rows
        # unless the parameter is marked CV_ND in the header.
        scene = make_scene(8, 8, seed=11)
        K = np.asarray(scene.cameraMatrices[0])
        reference = solve(scene, [K])
        for form, Kv, dv in [('3x3 array', K, None), ('3x3 array, 5 zero coefficients', K, np.zeros(5))]:
            count, R, t = solve(scene, Kv, dv)[:3]
            self.assertEqual(count, reference[0], form)
            np.testing.assert_allclose(R, reference[1], atol=1e-12, err_msg=form)
            np.testing.assert_allclose(t, reference[2], atol=1e-12, err_msg=form)

    def test_input_types(self):
        # float32 observations and a Rodrigues vector for R12 give the same pose.
        scene = make_scene(10, 10, seed=5)
        rvec12, _ = cv.Rodrigues(scene.R12)
        f32 = lambda a: np.asarray(a, dtype=np.float32)
        count, R, t = cv.tripose.estimatePoseLinePoint(
            f32(scene.points1), f32(scene.points2), f32(scene.points3),
            f32(scene.lines1), f32(scene.lines2), f32(scene.lines3),
            scene.cameraMatrices, None, rvec12, scene.t12)[:3]
        self.assertGreaterEqual(count, 1)
        # float32 pixels carry ~1e-5 px of rounding: micro-radians at this geometry (as in C++).
        self.check_pose(R, t, scene, 1e-4, 1e-3, 'float32 input')

    def test_bad_input(self):
        # The bad-input catalogue of test_estimate_pose_bad_input.cpp through cv2.tripose: each kind
        # breaks one thing in a valid problem and must raise cv.error naming the argument. Kinds of
        # the shared inputs go through all three functions. Not expressible from Python: an Rs
        # output that is not a vector (outputs are returned, always as lists).
        scene = make_scene(3, 3, seed=1)
        K = np.asarray(scene.cameraMatrices[0])
        valid = dict(points1=scene.points1, points2=scene.points2, points3=scene.points3,
                     lines1=scene.lines1, lines2=scene.lines2, lines3=scene.lines3,
                     cameraMatrix=[K], distCoeffs=None, R12=scene.R12, t12=scene.t12)

        def call(api, changes, params=None, method=None, R=None, t=None):
            args = dict(valid)
            args.update(changes)
            if api == 'linear':
                extra = {} if method is None else dict(method=method)
                return cv.tripose.estimatePoseLinePoint(**dict(args, **extra))[0]
            if api == 'ransac':
                return cv.tripose.estimatePoseLinePointRansac(
                    **dict(args, params=params or params_without_floor()))[0]
            R0 = np.array(scene.R) if R is None else R
            t0 = np.array(scene.t) if t is None else t
            return cv.tripose.refinePoseLinePoint(
                **dict(args, R=R0, t=t0, params=params or cv.tripose.RefineParams()))[0]

        def names(message, argument):
            # A whole word: 'R' is not named by 'R12' or 'Rodrigues'.
            return re.search(r'(?<![\w.])' + re.escape(argument) + r'(?!\w)', message) is not None

        def expect_error(kind, argument, apis=('linear', 'ransac', 'refine'), **kw):
            for api in apis:
                with self.assertRaises(cv.error, msg='%s through %s' % (kind, api)) as ctx:
                    call(api, **kw)
                message = getattr(ctx.exception, 'err', str(ctx.exception))
                self.assertTrue(names(message, argument),
                                '%s through %s: message does not name %s: %s' % (kind, api, argument, message))

        # The unbroken problem passes every function: each rejection is caused by its one change.
        self.assertGreater(call('linear', {}), 0)
        self.assertGreater(call('ransac', {}), 0)
        self.assertTrue(np.isfinite(call('refine', {})))

        nan, inf = np.nan, np.inf

        def with_value(a, index, x):
            a = np.array(a, dtype=np.float64)
            a[index] = x
            return a

        first = lambda n: dict(points1=scene.points1[:n[0]], points2=scene.points2[:n[0]], points3=scene.points3[:n[0]],
                               lines1=scene.lines1[:n[1]], lines2=scene.lines2[:n[1]], lines3=scene.lines3[:n[1]])
        segment = np.array(scene.lines2, dtype=np.float64)
        segment[1, 2:] = segment[1, :2]
        homogeneous = np.array([[1, 0, -300], [0, 1, -200], [1, 1, -500]], dtype=np.float64)
        bad_K = with_value(K, (0, 0), -1.0)
        d5 = np.zeros(5)

        # shapes and types of the observations
        expect_error('points_with_wrong_width', 'points2', changes=dict(points2=np.zeros((3, 3))))
        expect_error('points_with_integer_type', 'points1', changes=dict(points1=scene.points1.astype(np.int32)))
        expect_error('points_with_three_channels', 'points3', changes=dict(points3=np.zeros((3, 1, 3))))
        expect_error('lines_with_wrong_width', 'lines1', changes=dict(lines1=np.zeros((3, 5))))
        expect_error('lines_with_two_channels', 'lines2', changes=dict(lines2=np.zeros((3, 2, 2))))
        expect_error('segments_mixed_with_homogeneous_lines', 'lines3', changes=dict(lines3=np.ones((3, 3))))
        # counts
        expect_error('point_counts_differ', 'points3', changes=dict(points3=scene.points3[:2]))
        expect_error('points_missing_in_one_view', 'points2', changes=dict(points2=None))
        expect_error('line_counts_differ', 'lines2', changes=dict(lines2=scene.lines2[:1]))
        expect_error('fewer_than_four_features', 'at least 4 features', ('linear', 'ransac'), changes=first((1, 2)))
        expect_error('fewer_than_three_features_to_refine', 'at least 3 features', ('refine',), changes=first((1, 1)))
        nothing = dict(points1=None, points2=None, points3=None, lines1=None, lines2=None, lines3=None)
        expect_error('nothing_at_all', 'at least 4 features', ('linear', 'ransac'), changes=nothing)
        expect_error('nothing_at_all', 'at least 3 features', ('refine',), changes=nothing)
        # values of the observations
        expect_error('nan_in_points', 'points2', changes=dict(points2=with_value(scene.points2, (1, 0), nan)))
        expect_error('inf_in_lines', 'lines3', changes=dict(lines3=with_value(scene.lines3, (0, 3), inf)))
        expect_error('zero_length_segment', 'lines2', changes=dict(lines2=segment))
        expect_error('homogeneous_line_with_zero_normal', 'lines1',
                     changes=dict(lines1=with_value(homogeneous, (2, slice(0, 2)), 0.0), lines2=homogeneous,
                                  lines3=homogeneous))
        # pose of view 2
        expect_error('R12_not_a_rotation', 'R12', changes=dict(R12=1.1 * scene.R12))
        expect_error('R12_reflection', 'R12', changes=dict(R12=-scene.R12))
        expect_error('R12_wrong_shape', 'R12', changes=dict(R12=np.eye(2)))
        expect_error('R12_integer_type', 'R12', changes=dict(R12=np.eye(3, dtype=np.int32)))
        expect_error('nan_in_R12', 'R12', changes=dict(R12=with_value(scene.R12, (0, 1), nan)))
        expect_error('t12_zero', 't12', changes=dict(t12=np.zeros((3, 1))))
        expect_error('t12_wrong_size', 't12', changes=dict(t12=np.ones((4, 1))))
        expect_error('inf_in_t12', 't12', changes=dict(t12=with_value(scene.t12, 2, -inf)))
        # intrinsics
        expect_error('camera_matrix_negative_focal', 'cameraMatrix', changes=dict(cameraMatrix=[with_value(K, (0, 0), -800)]))
        expect_error('camera_matrix_zero_focal', 'cameraMatrix', changes=dict(cameraMatrix=[with_value(K, (1, 1), 0)]))
        expect_error('camera_matrix_singular', 'cameraMatrix', changes=dict(cameraMatrix=[with_value(K, (2, 2), 0)]))
        expect_error('camera_matrix_not_upper_triangular', 'cameraMatrix',
                     changes=dict(cameraMatrix=[with_value(K, (1, 0), 5)]))
        expect_error('camera_matrix_wrong_shape', 'cameraMatrix', changes=dict(cameraMatrix=[np.eye(3, 4)]))
        expect_error('camera_matrix_integer_type', 'cameraMatrix', changes=dict(cameraMatrix=[K.astype(np.int32)]))
        expect_error('nan_in_camera_matrix', 'cameraMatrix', changes=dict(cameraMatrix=[with_value(K, (0, 2), nan)]))
        expect_error('camera_matrix_missing', 'cameraMatrix', changes=dict(cameraMatrix=[]))
        expect_error('two_camera_matrices', 'cameraMatrix', changes=dict(cameraMatrix=[K, K]))
        expect_error('one_of_three_camera_matrices_bad', 'cameraMatrix[1]', changes=dict(cameraMatrix=[K, bad_K, K]))
        # distortion
        expect_error('distortion_with_wrong_count', 'distCoeffs', changes=dict(distCoeffs=[with_value(np.zeros(6), 0, 0.1)]))
        expect_error('distortion_as_matrix', 'distCoeffs', changes=dict(distCoeffs=[np.zeros((2, 4))]))
        expect_error('nan_in_distortion', 'distCoeffs', changes=dict(distCoeffs=[with_value(d5, 1, nan)]))
        expect_error('two_distortion_vectors', 'distCoeffs', changes=dict(distCoeffs=[d5, d5]))
        expect_error('homogeneous_lines_with_distortion', 'lines1',
                     changes=dict(lines1=homogeneous, lines2=homogeneous, lines3=homogeneous,
                                  distCoeffs=[np.array([0.1, 0, 0, 0])]))
        # flags of the linear solver
        expect_error('unknown_method', 'method', ('linear',), changes={}, method=42)

        # parameters of the robust estimator
        def ransac(**fields):
            p = cv.tripose.RansacParams()
            for name, value in fields.items():
                setattr(p, name, value)
            return p
        expect_error('ransac_threshold_zero', 'params.threshold', ('ransac',), changes={}, params=ransac(threshold=0.0))
        expect_error('ransac_threshold_not_finite', 'params.threshold', ('ransac',), changes={},
                     params=ransac(threshold=inf))
        expect_error('ransac_confidence_zero', 'params.confidence', ('ransac',), changes={},
                     params=ransac(confidence=0.0))
        expect_error('ransac_confidence_one', 'params.confidence', ('ransac',), changes={},
                     params=ransac(confidence=1.0))
        expect_error('ransac_max_iterations_zero', 'params.maxIterations', ('ransac',), changes={},
                     params=ransac(maxIterations=0))
        expect_error('ransac_min_inliers_negative', 'params.minInliers', ('ransac',), changes={},
                     params=ransac(minInliers=-1))

        # parameters and initial pose of the refinement
        def refine(**fields):
            p = cv.tripose.RefineParams()
            for name, value in fields.items():
                setattr(p, name, value)
            return p
        expect_error('refine_max_iterations_negative', 'params.maxIterations', ('refine',), changes={},
                     params=refine(maxIterations=-1))
        expect_error('refine_unknown_loss', 'params.loss', ('refine',), changes={}, params=refine(loss=7))
        expect_error('refine_loss_scale_zero', 'params.lossScale', ('refine',), changes={}, params=refine(lossScale=0.0))
        expect_error('refine_negative_tolerance', 'params.tolerance', ('refine',), changes={},
                     params=refine(tolerance=-1e-3))
        expect_error('refine_initial_R_not_a_rotation', 'R', ('refine',), changes={}, R=2.0 * np.array(scene.R))
        expect_error('refine_initial_R_nan', 'R', ('refine',), changes={}, R=with_value(scene.R, (2, 2), nan))
        expect_error('refine_initial_t_wrong_size', 't', ('refine',), changes={}, t=np.ones((2, 1)))
        expect_error('refine_initial_t_inf', 't', ('refine',), changes={}, t=with_value(scene.t, 0, inf))

    def test_robust(self):
        self.assertTrue(hasattr(cv.tripose, 'estimatePoseLinePointRansac'), 'cv.tripose.estimatePoseLinePointRansac is missing from the bindings')
        # 30 % wrong matches in view 3 and 0.5 px noise: RANSAC (with its final refinement) finds
        # the pose and separates the matches.
        for seed in range(3):
            scene = make_scene(40, 40, seed, noise=0.5, outliers=0.3)
            params = cv.tripose.RansacParams()
            params.seed = seed
            count, R, t, inl_points, inl_lines = cv.tripose.estimatePoseLinePointRansac(
                scene.points1, scene.points2, scene.points3,
                scene.lines1, scene.lines2, scene.lines3,
                scene.cameraMatrices, None, scene.R12, scene.t12, params=params)[:5]
            what = 'seed %d' % seed
            self.check_pose(R, t, scene, np.radians(0.5), 0.05, what)
            self.assertEqual(count, np.count_nonzero(inl_points) + np.count_nonzero(inl_lines), what)
            truth = np.concatenate([scene.pointInliers.ravel(), scene.lineInliers.ravel()]) != 0
            found = np.concatenate([inl_points.ravel(), inl_lines.ravel()]) != 0
            # A wrong match can fall within the threshold by chance; a true match beyond it is a
            # 4-sigma event at 2 px. Both kinds of mistake stay rare.
            self.assertGreaterEqual(np.count_nonzero(found & truth), 0.9 * np.count_nonzero(truth), what)
            self.assertLessEqual(np.count_nonzero(found & ~truth), 0.1 * np.count_nonzero(~truth) + 1, what)

    def test_refinement(self):
        self.assertTrue(hasattr(cv.tripose, 'refinePoseLinePoint'), 'cv.tripose.refinePoseLinePoint is missing from the bindings')
        # From the linear estimate on noisy data the maximum-likelihood refinement reaches the RMS
        # residual that Gaussian noise leaves after fitting: sigma * sqrt(1 - parameters / residuals)
        # (6 pose, 3 per point, 4 per line; 2 residuals per feature and view), within 25 % (the RMS
        # of ~100 remaining degrees of freedom varies by ~7 %). Its poses are, on average, closer to
        # the truth than the linear ones.
        sigma, n = 1.0, 20
        residuals = 3 * 2 * (n + n)
        expected_rms = sigma * np.sqrt(1.0 - (6 + 3 * n + 4 * n) / float(residuals))
        linear_rot, refined_rot = [], []
        for seed in range(6):
            scene = make_scene(n, n, seed, noise=sigma)
            count, R, t = solve(scene)[:3]
            self.assertGreaterEqual(count, 1)
            R0 = R.copy()
            rms, R1, t1, points3d, lines3d, covariance, noise_variance = cv.tripose.refinePoseLinePoint(
                scene.points1, scene.points2, scene.points3,
                scene.lines1, scene.lines2, scene.lines3,
                scene.cameraMatrices, None, scene.R12, scene.t12, R, t)
            what = 'seed %d' % seed
            # The pose's covariance for 1 px noise (doc/conventions.md): 6x6, symmetric positive definite;
            # the noise-variance estimate near sigma^2.
            self.assertEqual(covariance.shape, (6, 6), what)
            self.assertLess(np.abs(covariance - covariance.T).max(), 1e-12 * np.abs(covariance).max(), what)
            self.assertGreater(np.linalg.eigvalsh(covariance).min(), 0, what)
            self.assertLess(abs(float(np.ravel(noise_variance)[0]) / sigma ** 2 - 1.0), 0.5, what)
            self.assertLess(abs(rms / expected_rms - 1.0), 0.25, '%s: RMS %.3f px, expected %.3f' % (what, rms, expected_rms))
            self.assertEqual(points3d.shape, (n, 3), what)
            self.assertEqual(lines3d.shape, (n, 6), what)
            self.check_pose(R1, t1, scene, np.radians(1.0), 0.05, what)
            linear_rot.append(rotation_error(R0, scene.R))
            refined_rot.append(rotation_error(R1, scene.R))
        self.assertLess(np.mean(refined_rot), np.mean(linear_rot))

    def test_stereo_scene_helper(self):
        # The rig scenes are exact: every observation a view makes is the projection of the
        # structure, view 4 follows view 3 through the rig, and the views that do not see a
        # feature hold a row of NaN.
        scene = make_rig_scene(12, 8, seed=3, missing=0.5)
        K = scene.cameraMatrices[0]
        R4, t4 = scene.poses[3]
        np.testing.assert_allclose(R4, scene.R12 @ scene.R, atol=1e-15)
        observed = [(scene.points1, scene.lines1), (scene.points2, scene.lines2), (scene.points3, scene.lines3),
                    (scene.points4, scene.lines4)]
        for v, ((Rv, tv), (points, lines)) in enumerate(zip(scene.poses, observed)):
            seen_p = np.ones(12, bool) if v < 2 else (scene.pointVisibility & (1 << (v - 2))) != 0
            seen_l = np.ones(8, bool) if v < 2 else (scene.lineVisibility & (1 << (v - 2))) != 0
            self.assertTrue(np.all(np.isnan(points[~seen_p])) and np.all(np.isnan(lines[~seen_l])))
            np.testing.assert_allclose(project(K, Rv, tv, scene.points3d)[0][seen_p], points[seen_p], atol=1e-9)
            np.testing.assert_allclose(project(K, Rv, tv, scene.lines3d[:, :3])[0][seen_l], lines[seen_l, :2], atol=1e-9)
            np.testing.assert_allclose(project(K, Rv, tv, scene.lines3d[:, 3:])[0][seen_l], lines[seen_l, 2:], atol=1e-9)
        self.assertEqual(np.count_nonzero(scene.pointVisibility == SEEN_IN_BOTH), 6)

    def test_stereo_noise_free(self):
        self.assertTrue(hasattr(cv.tripose, 'estimatePoseLinePointStereo'), 'cv.tripose.estimatePoseLinePointStereo is missing from the bindings')
        # Three features seen by both time-B views, or more, some seen by one of them only: the best
        # candidate is the exact motion, with the metric scale of the rig.
        for num_points, num_lines, missing in [(3, 0, 0.0), (0, 3, 0.0), (2, 1, 0.0), (1, 2, 0.0), (10, 10, 0.0),
                                                (10, 10, 0.5), (8, 8, 1.0)]:
            for seed in range(3):
                scene = make_rig_scene(num_points, num_lines, seed, missing=missing)
                what = '%d points, %d lines, %g missing, seed %d' % (num_points, num_lines, missing, seed)
                count, R, t, Rs, ts, errors = cv.tripose.estimatePoseLinePointStereo(**rig_args(scene))[:6]
                self.assertGreaterEqual(count, 1, what)
                self.assertEqual(len(Rs), count, what)
                self.assertEqual(np.asarray(errors).size, count, what)
                self.check_pose(R, t, scene, EXACT_ROTATION_RAD, EXACT_TRANSLATION, what)

    def test_stereo_missing_views_and_refined_candidates(self):
        self.assertTrue(hasattr(cv.tripose, 'estimatePoseLinePointStereo'), 'cv.tripose.estimatePoseLinePointStereo is missing from the bindings')
        # Every feature seen by view 4 only: points3 and lines3 may be None (the view sees nothing);
        # float32 arrays keep their NaN rows; POSE_LINEAR_REFINE is exact on exact data.
        only4 = make_rig_scene(3, 3, seed=4, visibility=[SEEN_IN_VIEW4] * 6)
        count, R, t = cv.tripose.estimatePoseLinePointStereo(**rig_args(only4, points3=None, lines3=None))[:3]
        self.assertGreaterEqual(count, 1)
        self.check_pose(R, t, only4, EXACT_ROTATION_RAD, EXACT_TRANSLATION, 'view 4 only')
        scene = make_rig_scene(6, 6, seed=5, missing=0.5)
        f32 = dict((k, np.asarray(getattr(scene, k), dtype=np.float32)) for k in
                   ('points1', 'points2', 'points3', 'points4', 'lines1', 'lines2', 'lines3', 'lines4'))
        count, R, t = cv.tripose.estimatePoseLinePointStereo(**rig_args(scene, **f32))[:3]
        self.assertGreaterEqual(count, 1)
        self.check_pose(R, t, scene, 1e-4, 1e-3, 'float32 with NaN rows')
        count, R, t, Rs, ts, errors = cv.tripose.estimatePoseLinePointStereo(
            **rig_args(scene, method=cv.tripose.POSE_LINEAR_REFINE))[:6]
        self.assertGreaterEqual(count, 1)
        self.check_pose(R, t, scene, EXACT_ROTATION_RAD, EXACT_TRANSLATION, 'POSE_LINEAR_REFINE')
        self.assertLess(float(np.asarray(errors).ravel()[0]), 1e-6)

    def test_stereo_robust(self):
        self.assertTrue(hasattr(cv.tripose, 'estimatePoseLinePointStereoRansac'), 'cv.tripose.estimatePoseLinePointStereoRansac is missing from the bindings')
        # 30 % wrong matches at time B, 0.5 px noise, a fifth of the features seen by one time-B view:
        # the pose and the masks. (These seeds were checked through tripose_estimate, which calls
        # the same function; the C++ tests measure how often a scene defeats the estimator.)
        for seed in range(3):
            scene = make_rig_scene(60, 30, seed, noise=0.5, outliers=0.3, missing=0.2)
            params = cv.tripose.RansacParams()
            params.seed = seed
            count, R, t, inl_points, inl_lines = cv.tripose.estimatePoseLinePointStereoRansac(
                **rig_args(scene, params=params))[:5]
            what = 'seed %d' % seed
            self.check_pose(R, t, scene, np.radians(0.5), 0.05, what)
            self.assertEqual(count, np.count_nonzero(inl_points) + np.count_nonzero(inl_lines), what)
            self.assertEqual(np.asarray(inl_points).size, 60, what)
            self.assertEqual(np.asarray(inl_lines).size, 30, what)
            truth = np.concatenate([scene.pointInliers.ravel(), scene.lineInliers.ravel()]) != 0
            found = np.concatenate([np.asarray(inl_points).ravel(), np.asarray(inl_lines).ravel()]) != 0
            self.assertGreaterEqual(np.count_nonzero(found & truth), 0.95 * np.count_nonzero(truth), what)
            self.assertLessEqual(np.count_nonzero(found & ~truth), 0.05 * np.count_nonzero(~truth) + 1, what)

    def test_stereo_refinement(self):
        self.assertTrue(hasattr(cv.tripose, 'refinePoseLinePointStereo'), 'cv.tripose.refinePoseLinePointStereo is missing from the bindings')
        # Noise-free, from 1 degree and 5 % off: the exact motion and structure.
        rng = np.random.default_rng(8)
        for seed in range(4):
            scene = make_rig_scene(8, 8, seed, missing=0.3)
            R0 = axis_angle(rng, np.radians(1.0)) @ scene.R
            step = rng.normal(size=(3, 1))
            t0 = scene.t + 0.05 * np.linalg.norm(scene.t) * step / np.linalg.norm(step)
            params = cv.tripose.RefineParams()
            params.maxIterations = 100
            rms, R, t, points3d, lines3d = cv.tripose.refinePoseLinePointStereo(
                **rig_args(scene, R=R0, t=t0, params=params))[:5]
            what = 'seed %d' % seed
            self.assertLess(rms, 1e-6, what)
            self.check_pose(R, t, scene, EXACT_ROTATION_RAD, EXACT_TRANSLATION, what)
            self.assertEqual(points3d.shape, (8, 3), what)
            self.assertEqual(lines3d.shape, (8, 6), what)

    def test_stereo_bad_input(self):
        self.assertTrue(hasattr(cv.tripose, 'estimatePoseLinePointStereo'), 'cv.tripose.estimatePoseLinePointStereo is missing from the bindings')
        # The stereo kinds of the C++ bad-input catalogue: each breaks one thing in a valid rig
        # problem (point 1 seen by view 4 only, point 3 and line 2 by view 3 only) and must raise
        # cv.error naming the argument, through the three stereo functions.
        scene = make_rig_scene(4, 3, seed=1, visibility=[SEEN_IN_BOTH, SEEN_IN_VIEW4, SEEN_IN_BOTH, SEEN_IN_VIEW3,
                                                         SEEN_IN_BOTH, SEEN_IN_BOTH, SEEN_IN_VIEW3])
        K = scene.cameraMatrices[0]

        def call(api, changes):
            args = rig_args(scene, cameraMatrix=[K])
            args.update(changes)
            if api == 'linear':
                return cv.tripose.estimatePoseLinePointStereo(**args)[0]
            if api == 'ransac':
                return cv.tripose.estimatePoseLinePointStereoRansac(**dict(args, params=params_without_floor()))[0]
            return cv.tripose.refinePoseLinePointStereo(**dict(args, R=np.array(scene.R), t=np.array(scene.t)))[0]

        def expect_error(kind, argument, changes, apis=('linear', 'ransac', 'refine')):
            for api in apis:
                with self.assertRaises(cv.error, msg='%s through %s' % (kind, api)) as ctx:
                    call(api, changes)
                message = getattr(ctx.exception, 'err', str(ctx.exception))
                self.assertTrue(names_argument(message, argument),
                                '%s through %s: message does not name %s: %s' % (kind, api, argument, message))

        self.assertGreater(call('linear', {}), 0)
        self.assertGreater(call('ransac', {}), 0)
        self.assertTrue(np.isfinite(call('refine', {})))

        def with_row(a, row, value, col=slice(None)):
            a = np.array(a, dtype=np.float64)
            a[row, col] = value
            return a

        nan, inf = np.nan, np.inf
        bad_K = np.array(K)
        bad_K[1, 1] = -5.0
        expect_error('points4_with_another_row_count', 'points4', dict(points4=scene.points4[:3]))
        expect_error('lines4_with_another_row_count', 'lines4', dict(lines4=np.zeros((5, 4))))
        expect_error('points3_with_wrong_width', 'points3', dict(points3=np.zeros((4, 3))))
        expect_error('lines4_homogeneous_beside_segments', 'lines4', dict(lines4=np.ones((3, 3))))
        expect_error('partly_nan_point_row', 'points4', dict(points4=with_row(scene.points4, 0, nan, 1)))
        expect_error('partly_nan_line_row', 'lines3', dict(lines3=with_row(scene.lines3, 1, nan, 2)))
        expect_error('inf_in_points3', 'points3', dict(points3=with_row(scene.points3, 0, inf, 0)))
        expect_error('nan_row_in_a_time_A_view', 'points1', dict(points1=with_row(scene.points1, 0, nan)))
        expect_error('point_missing_in_both_views_3_and_4', 'points4', dict(points4=with_row(scene.points4, 1, nan)))
        expect_error('line_missing_in_both_views_3_and_4', 'lines3', dict(lines3=with_row(scene.lines3, 2, nan)))
        expect_error('no_time_B_points_at_all', 'points3', dict(points3=None, points4=None))
        expect_error('three_camera_matrices', 'cameraMatrix', dict(cameraMatrix=[K, K, K]))
        expect_error('one_of_four_camera_matrices_bad', 'cameraMatrix[3]', dict(cameraMatrix=[K, K, K, bad_K]))
        expect_error('three_distortion_vectors', 'distCoeffs', dict(distCoeffs=[np.zeros(5)] * 3))
        expect_error('R12_not_a_rotation', 'R12', dict(R12=1.1 * scene.R12))
        expect_error('t12_zero', 't12', dict(t12=np.zeros((3, 1))))
        one = dict(points1=scene.points1[:1], points2=scene.points2[:1], points3=scene.points3[:1],
                   points4=scene.points4[:1], lines1=None, lines2=None, lines3=None, lines4=None)
        expect_error('fewer_than_two_features', 'at least 2 features', one, ('linear', 'refine'))
        expect_error('fewer_than_two_features', 'at least 3 features', one, ('ransac',))
        expect_error('unknown_method', 'method', dict(method=3), ('linear',))

    def test_multiview(self):
        self.assertTrue(hasattr(cv.tripose, 'refinePoseMultiView'), 'cv.tripose.refinePoseMultiView is missing from the bindings')
        # Registration against four known views that each see a random subset of the features:
        # exact without noise (linear and refined), the inliers found among gross outliers.
        for seed in range(3):
            scene = make_multiview_scene(4, 12, 12, seed)
            what = 'seed %d' % seed
            count, R, t = cv.tripose.estimatePoseMultiView(scene.points, scene.lines, scene.K, None, scene.Rs,
                                                           scene.ts)[:3]
            self.assertGreaterEqual(count, 1, what)
            self.check_pose(R, t, scene, EXACT_ROTATION_RAD, EXACT_TRANSLATION, what)
            rvec = cv.Rodrigues(scene.R)[0] + 0.01
            rms, R1, t1 = cv.tripose.refinePoseMultiView(scene.points, scene.lines, scene.K, None, scene.Rs,
                                                         scene.ts, rvec, scene.t + 0.2)[:3]
            self.assertLess(rms, 1e-6, what)
            self.assertEqual(R1.shape, (3, 3), what)  # a rotation vector in, a matrix out
            self.check_pose(R1, t1, scene, EXACT_ROTATION_RAD, EXACT_TRANSLATION, what)
        scene = make_multiview_scene(4, 30, 10, 7, outliers=0.3)
        params = cv.tripose.RansacParams()
        params.seed = 1
        inliers, R, t, point_mask, line_mask = cv.tripose.estimatePoseMultiViewRansac(
            scene.points, scene.lines, scene.K, None, scene.Rs, scene.ts, params=params)[:5]
        self.check_pose(R, t, scene, EXACT_ROTATION_RAD, EXACT_TRANSLATION, 'robust')
        np.testing.assert_array_equal(point_mask.ravel(), scene.pointInliers)
        self.assertTrue(np.all(line_mask == 1))
        try:
            cv.tripose.estimatePoseMultiView(scene.points[:2] + scene.points[-1:], scene.lines[:2] + scene.lines[-1:],
                                             scene.K, None, scene.Rs[:1], scene.ts[:1])
            self.fail('one known view was accepted')
        except cv.error as e:
            self.assertTrue(names_argument(str(e), 'Rs'), str(e))

    def test_multiview_several_poses(self):
        self.assertTrue(hasattr(cv.tripose, 'adjustPosesMultiView'), 'cv.tripose.adjustPosesMultiView is missing from the bindings')
        # Views 0 and 1 fixed, the other known views and the new one moved off: the joint refinement
        # returns every pose exactly; the fixed ones come back as given.
        scene = make_multiview_scene(4, 20, 20, 11)
        Rs = list(scene.Rs) + [scene.R]
        ts = list(scene.ts) + [scene.t]
        rng = np.random.default_rng(2)
        start_R = [R if v < 2 else cv.Rodrigues(cv.Rodrigues(R)[0] + rng.uniform(-0.02, 0.02, (3, 1)))[0]
                   for v, R in enumerate(Rs)]
        start_t = [t if v < 2 else t + rng.uniform(-0.3, 0.3, (3, 1)) for v, t in enumerate(ts)]
        fixed = np.array([1, 1, 0, 0, 0], np.uint8)
        rms, refined_R, refined_t, points3d, lines3d = cv.tripose.adjustPosesMultiView(
            scene.points, scene.lines, scene.K, None, fixed, start_R, start_t)
        self.assertLess(rms, 1e-6)
        self.assertEqual(len(refined_R), 5)
        self.assertEqual(points3d.shape, (20, 3))
        self.assertEqual(lines3d.shape, (20, 6))
        for v in range(5):
            self.assertLess(rotation_error(refined_R[v], Rs[v]), EXACT_ROTATION_RAD, 'view %d' % v)
            self.assertLess(translation_error(refined_t[v], ts[v]), EXACT_TRANSLATION, 'view %d' % v)
        for bad, name in (([1, 0, 0, 0, 0], 'fixedViews'), ([1, 1, 1, 1, 1], 'fixedViews'), ([1, 1, 0], 'fixedViews')):
            try:
                cv.tripose.adjustPosesMultiView(scene.points, scene.lines, scene.K, None, np.array(bad, np.uint8),
                                                start_R, start_t)
                self.fail('fixedViews %s was accepted' % bad)
            except cv.error as e:
                self.assertTrue(names_argument(str(e), name), str(e))

    def test_triangulate_multiview(self):
        self.assertTrue(hasattr(cv.tripose, 'triangulateMultiView'), 'cv.tripose.triangulateMultiView is missing from the bindings')
        # Every view posed (the known views and the new one at its true pose): the structure
        # reprojects onto every observation, NaN errors where a view does not see a feature.
        scene = make_multiview_scene(4, 12, 12, 5)
        Rs = list(scene.Rs) + [scene.R]
        ts = list(scene.ts) + [scene.t]
        count, points3d, lines3d, point_errors, line_errors = cv.tripose.triangulateMultiView(
            scene.points, scene.lines, scene.K, None, Rs, ts)
        self.assertEqual(count, 24)
        self.assertEqual(points3d.shape, (12, 3))
        self.assertEqual(lines3d.shape, (12, 6))
        self.assertEqual(point_errors.shape, (12, 5))
        self.assertEqual(line_errors.shape, (12, 5))
        for v in range(5):
            seen = ~np.isnan(np.asarray(scene.points[v], np.float64)[:, 0])
            np.testing.assert_array_equal(np.isnan(point_errors[:, v]), ~seen)
            self.assertTrue(np.all(point_errors[seen, v] < 1e-6), 'view %d' % v)
            X = np.asarray(points3d[seen], np.float64)
            x = (scene.K @ (np.asarray(Rs[v], np.float64) @ X.T + np.asarray(ts[v], np.float64).reshape(3, 1))).T
            x = x[:, :2] / x[:, 2:]
            self.assertLess(np.max(np.abs(x - np.asarray(scene.points[v], np.float64)[seen])), 1e-6, 'view %d' % v)
        self.assertTrue(np.all(np.nan_to_num(line_errors, nan=0.0) < 1e-6))
        try:
            cv.tripose.triangulateMultiView(scene.points[:1], scene.lines[:1], scene.K, None, Rs[:1], ts[:1])
            self.fail('one view was accepted')
        except cv.error as e:
            self.assertTrue(names_argument(str(e), 'Rs'), str(e))

    def test_agrees_with_the_package(self):
        # The problems of test/data/agreement/cv2_agreement.npz (three views, a stereo rig, several
        # known views; 0.5 px noise, 25 % wrong matches for RANSAC) and the tripose package's
        # solutions of them, recorded by python/tests/test_cv2_agreement.py, which also checks the
        # package against them: cv2.tripose gives the same, so the two agree without both being
        # installed in one Python. Every optional output in the order the C++ functions declare it.
        path = self.find_file('agreement/cv2_agreement.npz', required=False)
        if path is None:
            self.skipTest('test/data/agreement/cv2_agreement.npz not found (OPENCV_TEST_DATA_PATH=<repo>/test/data)')
        with np.load(path, allow_pickle=False) as data:
            p = {key: data[key] for key in data.files}
        params = cv.tripose.RansacParams()
        params.seed = int(p['seed'])
        views = len(p['multi_Rs']) + 1
        multi_points = [p['multi_points%d' % v] for v in range(views)]
        multi_lines = [p['multi_lines%d' % v] for v in range(views)]
        multi_ransac = (multi_points[:-1] + [p['multi_ransac_points']], multi_lines[:-1] + [p['multi_ransac_lines']])
        rig_late = lambda prefix: [p[prefix + 'points3'], p[prefix + 'points4']]
        rig_late_lines = lambda prefix: [p[prefix + 'lines3'], p[prefix + 'lines4']]
        three = (p['three_K'], None, p['three_R12'], p['three_t12'])
        rig = (p['rig_K'], None, p['rig_R12'], p['rig_t12'])
        linear = {
            'three': cv.tripose.estimatePoseLinePoint(p['three_points1'], p['three_points2'], p['three_points3'],
                                                      p['three_lines1'], p['three_lines2'], p['three_lines3'], *three),
            'rig': cv.tripose.estimatePoseLinePointStereo(p['rig_points1'], p['rig_points2'], *rig_late('rig_'),
                                                          p['rig_lines1'], p['rig_lines2'], *rig_late_lines('rig_'),
                                                          *rig),
            'multi': cv.tripose.estimatePoseMultiView(multi_points, multi_lines, p['multi_K'], None,
                                                      list(p['multi_Rs']), list(p['multi_ts'])),
        }
        robust = {
            'three': cv.tripose.estimatePoseLinePointRansac(
                p['three_points1'], p['three_points2'], p['three_ransac_points3'], p['three_lines1'],
                p['three_lines2'], p['three_ransac_lines3'], *three, params=params),
            'rig': cv.tripose.estimatePoseLinePointStereoRansac(
                p['rig_points1'], p['rig_points2'], *rig_late('rig_ransac_'), p['rig_lines1'], p['rig_lines2'],
                *rig_late_lines('rig_ransac_'), *rig, params=params),
            'multi': cv.tripose.estimatePoseMultiViewRansac(multi_ransac[0], multi_ransac[1], p['multi_K'], None,
                                                            list(p['multi_Rs']), list(p['multi_ts']), params=params),
        }

        def expect_poses(Rs, ts, key_R, key_t, what):
            # The same core on the same doubles: builds differ in rounding only.
            R0 = p[key_R].reshape(-1, 3, 3)
            t0 = p[key_t].reshape(-1, 3)
            self.assertEqual(len(Rs), len(R0), what)
            scale = max(1.0, float(np.abs(t0).max()))
            for k in range(len(R0)):
                self.assertLess(np.abs(np.asarray(Rs[k], np.float64).reshape(3, 3) - R0[k]).max(), 1e-8, what)
                self.assertLess(np.abs(np.asarray(ts[k], np.float64).ravel() - t0[k]).max(), 1e-8 * scale, what)

        for family in ('three', 'rig', 'multi'):
            count, R, t, Rs, ts = linear[family][:5]
            self.assertEqual(count, len(Rs), family)
            expect_poses(Rs, ts, family + '_linear_Rs', family + '_linear_ts', family + ' linear')
            key = family + '_ransac_'
            n, R, t, point_inliers, line_inliers, Rs, ts, errors, covariance, noise_variance = robust[family]
            what = family + ' RANSAC'
            self.assertEqual(n, int(p[key + 'num_inliers']), what)
            np.testing.assert_array_equal(np.asarray(point_inliers).ravel() != 0, p[key + 'point_inliers'], what)
            np.testing.assert_array_equal(np.asarray(line_inliers).ravel() != 0, p[key + 'line_inliers'], what)
            expect_poses([R], [t], key + 'R', key + 't', what)
            expect_poses(Rs, ts, key + 'candidate_Rs', key + 'candidate_ts', what + ' candidates')
            rms0 = p[key + 'candidate_rms']
            self.assertEqual(np.asarray(errors).size, rms0.size, what)
            self.assertLess(np.abs(np.asarray(errors, np.float64).ravel() - rms0).max(), 1e-8 * rms0.max(), what)
            C0 = p[key + 'covariance']
            self.assertLess(np.linalg.norm(np.asarray(covariance, np.float64) - C0), 1e-6 * np.linalg.norm(C0), what)
            s20 = float(p[key + 'noise_variance'])
            self.assertLess(abs(float(np.asarray(noise_variance).ravel()[0]) - s20), 1e-8 * s20, what)


if __name__ == '__main__':
    NewOpenCVTests.bootstrap()
