#!/usr/bin/env python
"""Python bindings of the tripose module: synthetic three-view scenes solved through cv2.tripose.

Run inside an OpenCV build (scripts/test_intree.sh does it):
  OPENCV_PYTEST_FILTER=test_tripose python3 <opencv>/modules/python/test/test.py --repo <opencv>
"""

from __future__ import print_function

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


def make_scene(num_points, num_lines, seed, noise=0.0, outliers=0.0):
    params = cv.tripose.SyntheticSceneParams()
    params.numPoints = num_points
    params.numLines = num_lines
    params.noiseSigma = noise
    params.outlierRatio = outliers
    params.seed = seed
    return cv.tripose.generateSyntheticScene(params)


def solve(scene, cameraMatrix=None, distCoeffs=None):
    """estimatePoseLinePoint on a scene; returns (count, R, t, Rs, ts, errors)."""
    K = scene.cameraMatrices if cameraMatrix is None else cameraMatrix
    return cv.tripose.estimatePoseLinePoint(
        scene.points1, scene.points2, scene.points3,
        scene.lines1, scene.lines2, scene.lines3,
        K, distCoeffs, scene.R12, scene.t12)


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

    def test_scene_generator(self):
        scene = make_scene(7, 5, seed=3)
        self.assertEqual(scene.points1.shape, (7, 2))
        self.assertEqual(scene.lines3.shape, (5, 4))
        self.assertEqual(len(scene.cameraMatrices), 3)
        np.testing.assert_allclose(scene.R @ scene.R.T, np.eye(3), atol=1e-12)
        self.assertAlmostEqual(np.linalg.det(scene.R), 1.0, places=12)
        # Noise-free points project exactly: x3 ~ K (R X + t).
        X = scene.points3d
        x = (scene.cameraMatrices[2] @ (scene.R @ X.T + scene.t.reshape(3, 1))).T
        np.testing.assert_allclose(x[:, :2] / x[:, 2:], scene.points3, atol=1e-9)

    def test_scene_parameters_round_trip(self):
        # std::vector<Mat> and Size members of a CV_EXPORTS_W_SIMPLE struct, set from Python.
        K = np.array([[500.0, 0, 300], [0, 520.0, 250], [0, 0, 1]])
        params = cv.tripose.SyntheticSceneParams()
        params.numPoints = 6
        params.numLines = 0
        params.imageSize = (600, 500)
        params.cameraMatrices = [K]
        self.assertEqual(tuple(params.imageSize), (600, 500))
        scene = cv.tripose.generateSyntheticScene(params)
        for Ki in scene.cameraMatrices:
            np.testing.assert_array_equal(Ki, K)
        self.assertTrue(np.all((scene.points3 >= -0.5) & (scene.points3 < np.array([600, 500]) - 0.5)))

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
        scene = make_scene(6, 6, seed=2)

        def expect_error(mentions, **changes):
            args = dict(points1=scene.points1, points2=scene.points2, points3=scene.points3,
                        lines1=scene.lines1, lines2=scene.lines2, lines3=scene.lines3,
                        cameraMatrix=scene.cameraMatrices, distCoeffs=None,
                        R12=scene.R12, t12=scene.t12)
            args.update(changes)
            with self.assertRaises(cv.error) as ctx:
                cv.tripose.estimatePoseLinePoint(**args)
            self.assertIn(mentions, str(ctx.exception))

        expect_error('points2', points2=scene.points2[:5])          # count differs from view 1
        expect_error('lines3', lines3=scene.lines3[:, :2].copy())    # neither 4 nor 3 columns
        expect_error('t12', t12=np.zeros((3, 1)))                    # the scale would be undefined
        expect_error('R12', R12=2.0 * scene.R12)                     # not a rotation
        expect_error('cameraMatrix', cameraMatrix=[np.eye(2)])       # not 3x3
        expect_error('distCoeffs', distCoeffs=[np.zeros(3)])         # not 4, 5, 8, 12 or 14 values

    def test_robust(self):
        if not hasattr(cv.tripose, 'estimatePoseLinePointRansac'):
            self.skipTest('estimatePoseLinePointRansac is not in this build of the module')
        # 30 % wrong matches in view 3 and 0.5 px noise: RANSAC (with its final refinement) finds
        # the pose and separates the matches.
        for seed in range(3):
            scene = make_scene(40, 40, seed, noise=0.5, outliers=0.3)
            params = cv.tripose.RansacParams()
            params.seed = seed
            count, R, t, inl_points, inl_lines = cv.tripose.estimatePoseLinePointRansac(
                scene.points1, scene.points2, scene.points3,
                scene.lines1, scene.lines2, scene.lines3,
                scene.cameraMatrices, None, scene.R12, scene.t12, params=params)
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
        if not hasattr(cv.tripose, 'refinePoseLinePoint'):
            self.skipTest('refinePoseLinePoint is not in this build of the module')
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
            rms, R1, t1, points3d, lines3d = cv.tripose.refinePoseLinePoint(
                scene.points1, scene.points2, scene.points3,
                scene.lines1, scene.lines2, scene.lines3,
                scene.cameraMatrices, None, scene.R12, scene.t12, R, t)
            what = 'seed %d' % seed
            self.assertLess(abs(rms / expected_rms - 1.0), 0.25, '%s: RMS %.3f px, expected %.3f' % (what, rms, expected_rms))
            self.assertEqual(points3d.shape, (n, 3), what)
            self.assertEqual(lines3d.shape, (n, 6), what)
            self.check_pose(R1, t1, scene, np.radians(1.0), 0.05, what)
            linear_rot.append(rotation_error(R0, scene.R))
            refined_rot.append(rotation_error(R1, scene.R))
        self.assertLess(np.mean(refined_rot), np.mean(linear_rot))

if __name__ == '__main__':
    NewOpenCVTests.bootstrap()
