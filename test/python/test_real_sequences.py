"""The readers of the real-image benchmark sequences (real_sequences.py): their ground truth agrees
with their images (SIFT matches of neighbouring views lie on the epipolar lines of the ground-truth
poses and triangulate in front of both cameras, a wrong pairing does not), the ring order of
templeRing is the documented one, and the pose helpers and file writers do what they say."""
import math

import cv2
import numpy as np
import pytest

import real_sequences as rs

MAX_SIZE = 1600  # px: images are matched reduced to this longer side, as the front end detects


def reduced(path, K, max_size=MAX_SIZE):
    """The grey image at path reduced to max_size on its longer side (area averaging) and K for it:
    pixel centres map onto pixel centres, x' = (x + 0.5) / f - 0.5."""
    image = cv2.imread(str(path), cv2.IMREAD_GRAYSCALE)
    assert image is not None, f"{path}: cannot be read"
    h, w = image.shape
    if max(h, w) <= max_size:
        return image, np.asarray(K, np.float64)
    scale = max(h, w) / max_size
    size = (max(1, int(w / scale + 0.5)), max(1, int(h / scale + 0.5)))
    sx, sy = size[0] / w, size[1] / h
    S = np.array([[sx, 0, 0.5 * sx - 0.5], [0, sy, 0.5 * sy - 0.5], [0, 0, 1]])
    return cv2.resize(image, size, interpolation=cv2.INTER_AREA), S @ K


def sift_matches(seq, i, j, ratio=0.8):
    """Pixel positions (N, 2) of SIFT matches between views i and j (Lowe's ratio test, mutual), and the
    two views' K in the reduced images."""
    sift = cv2.SIFT_create(4000)
    found = []
    for v in (i, j):
        image, K = reduced(seq.image_paths[v], seq.K[v])
        keypoints, desc = sift.detectAndCompute(image, None)
        found.append((np.array([k.pt for k in keypoints], np.float64), desc, K))
    (xa, da, Ka), (xb, db, Kb) = found
    forward = cv2.BFMatcher(cv2.NORM_L2).knnMatch(da, db, k=2)
    backward = {m.queryIdx: m.trainIdx for m in cv2.BFMatcher(cv2.NORM_L2).match(db, da)}
    pairs = [(m.queryIdx, m.trainIdx) for m, n in (p for p in forward if len(p) == 2)
             if m.distance < ratio * n.distance and backward.get(m.trainIdx) == m.queryIdx]
    rows = np.array(pairs, int).reshape(-1, 2)
    return xa[rows[:, 0]], xb[rows[:, 1]], Ka, Kb


def symmetric_epipolar_distances(F, xa, xb):
    """For each match, the mean of the distances of xb to F xa and of xa to F^T xb (px)."""
    ha, hb = np.hstack([xa, np.ones((len(xa), 1))]), np.hstack([xb, np.ones((len(xb), 1))])
    la, lb = hb @ F, ha @ F.T  # lines in image a (of b's points) and in image b (of a's points)
    residual = np.abs(np.sum(hb * lb, axis=1))
    return 0.5 * residual * (1 / np.hypot(la[:, 0], la[:, 1]) + 1 / np.hypot(lb[:, 0], lb[:, 1]))


def in_front_fraction(Ka, Ra, ta, Kb, Rb, tb, xa, xb):
    """The fraction of the matches whose triangulated point lies in front of both cameras."""
    Pa, Pb = Ka @ np.hstack([Ra, ta.reshape(3, 1)]), Kb @ np.hstack([Rb, tb.reshape(3, 1)])
    X = cv2.triangulatePoints(Pa, Pb, xa.T.astype(np.float64), xb.T.astype(np.float64))
    X = X[:3] / X[3]
    depth_a = (Ra @ X + ta.reshape(3, 1))[2]
    depth_b = (Rb @ X + tb.reshape(3, 1))[2]
    return float(np.mean((depth_a > 0) & (depth_b > 0)))


def check_ground_truth(seq, i, j, wrong):
    """Views i and j of seq: their SIFT matches lie within 1.5 px (median) of the epipolar lines of the
    ground truth and, near those lines, triangulate in front of both cameras; under the wrong poses
    (Ra, ta, Rb, tb) the median is several times larger."""
    xa, xb, Ka, Kb = sift_matches(seq, i, j)
    assert len(xa) >= 50, f"{seq.name} {seq.ids[i]}-{seq.ids[j]}: only {len(xa)} matches"
    F = rs.fundamental_matrix(Ka, seq.R[i], seq.t[i], Kb, seq.R[j], seq.t[j])
    d = symmetric_epipolar_distances(F, xa, xb)
    median = float(np.median(d))
    print(f"{seq.name} {seq.ids[i]}-{seq.ids[j]}: {len(xa)} matches, median epipolar distance {median:.2f} px")
    assert median < 1.5, f"{seq.name} {seq.ids[i]}-{seq.ids[j]}: median epipolar distance {median:.2f} px"
    near = d < 2.0
    front = in_front_fraction(Ka, seq.R[i], seq.t[i], Kb, seq.R[j], seq.t[j], xa[near], xb[near])
    assert front > 0.9, f"{seq.name}: only {front:.0%} of the matches triangulate in front of both cameras"
    F_wrong = rs.fundamental_matrix(Ka, wrong[0], wrong[1], Kb, wrong[2], wrong[3])
    wrong_median = float(np.median(symmetric_epipolar_distances(F_wrong, xa, xb)))
    assert wrong_median > max(4 * median, 3.0), (f"{seq.name}: the wrong poses give a median of {wrong_median:.2f} px, "
                                                 f"the right ones {median:.2f} px")
    print(f"{seq.name}: under the wrong poses {wrong_median:.2f} px")
    return median, wrong_median


def test_fountain_p11_agrees_with_its_images():
    seq = rs.fountain_p11()
    assert len(seq) == 11 and (seq.width, seq.height) == (3072, 2048)
    # Images 0 and 1 under the poses of views 0 and 4, a pair that is not neighbours.
    check_ground_truth(seq, 0, 1, (seq.R[0], seq.t[0], seq.R[4], seq.t[4]))


def test_herz_jesus_p8_agrees_with_its_images():
    seq = rs.herz_jesus_p8()
    assert len(seq) == 8 and (seq.width, seq.height) == (3072, 2048)
    check_ground_truth(seq, 3, 4, (seq.R[3], seq.t[3], seq.R[7], seq.t[7]))


def test_temple_ring_agrees_with_its_images():
    seq = rs.temple_ring()
    assert len(seq) == 47 and (seq.width, seq.height) == (640, 480)
    # The neighbours 33 and 32 on the ring (5.1 degrees apart); wrong: 32's pose replaced by that of
    # file 13, 57 degrees further round (all neighbours on the ring have nearly one relative pose).
    check_ground_truth(seq, 1, 2, (seq.R[1], seq.t[1], seq.R[9], seq.t[9]))


def test_kitti_06_forward_agrees_with_its_images():
    seq = rs.kitti_06_forward()
    assert seq.ids == ["12-cam2", "13-cam2", "14-cam2", "17-cam2"] and (seq.width, seq.height) == (1226, 370)
    # The colour camera's K is P0's: the rectified cameras share their intrinsics.
    calib = rs.read_kitti_calib(rs.data_dir() / "kitti-06-frames" / "calib.txt")
    np.testing.assert_array_equal(seq.K[0], calib["P0"][:, :3])
    # Along a straight road every pose pair has its epipole ahead, and only the in-front test tells
    # the direction of travel; the stereo rig's sideways pose is the wrong one.
    rig = rs.relative_to_first(rs.kitti_06_stereo())
    check_ground_truth(seq, 2, 3, (np.eye(3), np.zeros(3), rig.R[1], rig.t[1]))
    # Travelling backwards puts the matches behind the cameras.
    xa, xb, Ka, Kb = sift_matches(seq, 2, 3)
    assert in_front_fraction(Ka, seq.R[3], seq.t[3], Kb, seq.R[2], seq.t[2], xa, xb) < 0.5


def test_kitti_06_stereo_agrees_with_its_images():
    seq = rs.kitti_06_stereo()
    rig = rs.relative_to_first(seq)
    assert rs.rotation_error_deg(rig.R[1], np.eye(3)) < 1e-9
    np.testing.assert_allclose(rig.t[1], [-0.537, 0, 0], atol=5e-4)  # the baseline (PROVENANCE.txt)
    forward = rs.kitti_06_forward(camera=0, frames=(12, 13))
    check_ground_truth(seq, 0, 1, (forward.R[0], forward.t[0], forward.R[1], forward.t[1]))


def test_model_house_agrees_with_its_images_and_camera_matrices():
    seq = rs.model_house()
    assert len(seq) == 10 and (seq.width, seq.height) == (768, 576)
    # Each view's K [R | t] is its .P file's matrix up to scale, with the mirrored world's Z flipped.
    for view, K in enumerate(seq.K):
        P = np.loadtxt(rs.vgg_dir() / "Model-House" / f"house.{view:03d}.P") @ np.diag([1.0, 1, -1, 1])
        M = K @ np.hstack([seq.R[view], seq.t[view].reshape(3, 1)])
        np.testing.assert_allclose(M / np.linalg.norm(M), P / np.linalg.norm(P) * np.sign(P[2, 3] * M[2, 3]),
                                   atol=1e-9)
    check_ground_truth(seq, 0, 1, (seq.R[0], seq.t[0], seq.R[6], seq.t[6]))


@pytest.mark.parametrize("reader", [rs.fountain_p11, rs.herz_jesus_p8, rs.temple_ring, rs.kitti_06_forward,
                                    rs.kitti_06_stereo, rs.model_house, rs.merton_college_1])
def test_readers_give_exact_rotations_and_consistent_views(reader):
    seq = reader()
    n = len(seq)
    assert n >= 2 and all(len(x) == n for x in (seq.K, seq.R, seq.t, seq.ids))
    for path, K, R, t in zip(seq.image_paths, seq.K, seq.R, seq.t):
        assert path.is_file()
        assert K.shape == (3, 3) and R.shape == (3, 3) and t.shape == (3,)
        np.testing.assert_allclose(R @ R.T, np.eye(3), atol=1e-12)
        assert abs(np.linalg.det(R) - 1) < 1e-12
        # The principal point lies near the image centre: K belongs to images of this size.
        assert abs(K[0, 2] - seq.width / 2) < 0.2 * seq.width and abs(K[1, 2] - seq.height / 2) < 0.2 * seq.height


def test_strecha_camera_file_is_read_as_camera_to_world():
    seq = rs.fountain_p11()
    path = rs.data_dir() / "strecha-fountain-P11" / "gt_dense_cameras" / "0000.jpg.camera"
    rows = [[float(v) for v in line.split()] for line in path.read_text().splitlines() if line.strip()]
    R_file, C = np.array(rows[4:7]), np.array(rows[7])
    np.testing.assert_allclose(seq.R[0], R_file.T, atol=2e-6)
    np.testing.assert_allclose(rs.camera_centre(seq.R[0], seq.t[0]), C, atol=1e-9)


def test_temple_ring_steps_are_the_documented_ones():
    seq = rs.temple_ring()
    assert seq.ids == rs.TEMPLE_RING_ORDER
    names = [p.name for p in seq.image_paths]
    assert names[:3] == ["templeR0034.png", "templeR0033.png", "templeR0032.png"]
    centres = seq.centres()
    # The angle between neighbours about the ring's centre, as PROVENANCE.txt gives them.
    offsets = centres - centres.mean(axis=0)
    angles = [math.degrees(math.acos(np.clip(a @ b / np.linalg.norm(a) / np.linalg.norm(b), -1, 1)))
              for a, b in zip(offsets, np.roll(offsets, -1, axis=0))]
    # PROVENANCE.txt gives 5.1 and 2.7 degrees to 34->33 and 33->32; the cameras have them one step
    # later (33->32, 32->47), and 34->33 is a regular step.
    documented = {(33, 32): 5.1, (32, 47): 2.7, (42, 13): 4.4, (30, 1): 0.0, (1, 31): 4.8, (31, 2): 2.6,
                  (5, 41): 32.2, (41, 40): 7.2, (40, 6): 3.9, (12, 39): 10.8}
    for (a, b), angle in zip(zip(seq.ids, seq.ids[1:] + seq.ids[:1]), angles):
        expected = documented.get((a, b))
        if expected is None:
            assert 7.0 <= angle <= 8.3, f"{a}->{b}: {angle:.1f} degrees"
        else:
            assert abs(angle - expected) < 0.06, f"{a}->{b}: {angle:.2f} degrees, documented {expected}"


def random_rotation(rng):
    return rs.quaternion_to_rotation(rng.normal(size=4))


def test_relative_to_first_keeps_relative_poses_and_scale():
    seq = rs.herz_jesus_p8()
    rel = rs.relative_to_first(seq)
    assert rs.rotation_error_deg(rel.R[0], np.eye(3)) < 1e-9 and np.linalg.norm(rel.t[0]) < 1e-12
    for i in range(len(seq)):
        Ra, ta = rs.relative_pose(seq.R[0], seq.t[0], seq.R[i], seq.t[i])
        assert rs.rotation_error_deg(rel.R[i], Ra) < 1e-9 and np.allclose(rel.t[i], ta)
    assert abs(rs.path_length(rel.R, rel.t) - rs.path_length(seq.R, seq.t)) < 1e-9
    # Distances between camera centres stay in metres.
    for i in range(1, len(seq)):
        assert abs(rs.position_error(rel.R[0], rel.t[0], rel.R[i], rel.t[i])
                   - rs.position_error(seq.R[0], seq.t[0], seq.R[i], seq.t[i])) < 1e-9


def test_pose_helpers():
    rng = np.random.default_rng(3)
    R = random_rotation(rng)
    axis = np.array([0.0, 0.6, 0.8])
    for degrees in (1e-6, 0.5, 30.0, 179.0):
        turn = cv2.Rodrigues(axis * math.radians(degrees))[0]
        assert rs.rotation_error_deg(turn @ R, R) == pytest.approx(degrees, rel=1e-6)
    t = np.array([1.0, -2.0, 3.0])
    assert np.allclose(rs.camera_centre(R, t), -R.T @ t)
    assert rs.position_error(R, t, R, t + R @ np.array([0.0, 0.0, 2.0])) == pytest.approx(2.0)
    # Centres at (0,0,0), (3,4,0), (3,4,12): a path of 5 + 12.
    centres = [np.zeros(3), np.array([3.0, 4, 0]), np.array([3.0, 4, 12])]
    assert rs.path_length([R] * 3, [-R @ c for c in centres]) == pytest.approx(17.0)
    M = R + 1e-6 * rng.normal(size=(3, 3))
    assert np.allclose(rs.nearest_rotation(M) @ rs.nearest_rotation(M).T, np.eye(3), atol=1e-14)
    assert rs.rotation_error_deg(rs.nearest_rotation(M), R) < 1e-3


def test_tum_round_trip(tmp_path):
    rng = np.random.default_rng(7)
    Rs = [random_rotation(rng) for _ in range(6)] + [np.diag([1.0, -1, -1]), np.diag([-1.0, 1, -1]),
                                                   np.diag([-1.0, -1, 1])]
    ts = [rng.normal(size=3) * 5 for _ in Rs]
    stamps = np.arange(len(Rs)) * 0.1 + 1e9
    path = tmp_path / "trajectory.txt"
    rs.write_tum(path, stamps, Rs, ts)
    read_stamps, read_Rs, read_ts = rs.read_tum(path)
    np.testing.assert_allclose(read_stamps, stamps, rtol=0, atol=1e-6)
    for R, t, Rr, tr in zip(Rs, ts, read_Rs, read_ts):
        assert rs.rotation_error_deg(R, Rr) < 1e-10
        np.testing.assert_allclose(tr, t, atol=1e-12)


def test_tum_lines_hold_the_camera_in_the_world(tmp_path):
    # A camera at (1, 2, 3) turned 90 degrees about the world's z axis (camera-to-world rotation).
    to_world = np.array([[0.0, -1, 0], [1, 0, 0], [0, 0, 1]])
    position = np.array([1.0, 2, 3])
    R, t = to_world.T, -to_world.T @ position
    path = tmp_path / "one.txt"
    rs.write_tum(path, [5.0], [R], [t])
    fields = [float(v) for v in path.read_text().splitlines()[-1].split()]
    assert fields[0] == 5.0
    np.testing.assert_allclose(fields[1:4], position, atol=1e-15)
    s = math.sqrt(0.5)
    np.testing.assert_allclose(fields[4:8], [0, 0, s, s], atol=1e-15)  # qx qy qz qw of to_world


def test_write_calibration_yaml(tmp_path):
    K = np.array([[700.0, 0, 600], [0, 710, 180], [0, 0, 1]])
    R = random_rotation(np.random.default_rng(1))
    t = np.array([0.1, 0.2, 0.3])
    path = tmp_path / "calib.yml"
    rs.write_calibration_yaml(path, K, dist=np.array([0.1, -0.01, 0, 0, 0]), R0=np.eye(3), t0=np.zeros(3),
                              R1=R, t1=t)
    fs = cv2.FileStorage(str(path), cv2.FILE_STORAGE_READ)
    read = {k: fs.getNode(k).mat() for k in ("K", "dist", "R0", "t0", "R1", "t1")}
    fs.release()
    np.testing.assert_array_equal(read["K"], K)
    assert read["dist"].shape == (5, 1) and read["t1"].shape == (3, 1)
    np.testing.assert_array_equal(read["R1"], R)
    np.testing.assert_array_equal(read["t1"].ravel(), t)
    # A list of K is written as K1, K2, ...; the pose keys are the caller's (here R12, t12).
    rs.write_calibration_yaml(path, [K, 2 * K], R12=R, t12=t)
    fs = cv2.FileStorage(str(path), cv2.FILE_STORAGE_READ)
    assert fs.getNode("K").empty() and fs.getNode("dist").empty()
    np.testing.assert_array_equal(fs.getNode("K2").mat(), 2 * K)
    np.testing.assert_array_equal(fs.getNode("t12").mat().ravel(), t)
    fs.release()
