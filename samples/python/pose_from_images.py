#!/usr/bin/env python3
"""The pose of a third camera from three images, in Python: the C++ sample tripose_images over the
tripose package (tripose.images: SIFT, EDLines segments fitted to their edges, LBD; tripose.match_triplets;
tripose.estimate_pose_line_point_ransac under the image front end's Cauchy loss).

    pose_from_images.py --calib calib.yml --images a.png b.png c.png --output result.yml
                        [--features points|lines|all] [--threshold px] [--seed n] [--max-image-size px]
                        [--problem-only]

calib.yml holds the calibration keys of a problem file: K or K1..K3, optional dist or
dist1..dist3, R12, t12 (view 2's pose; view 1 is the world frame). The result holds R, t,
num_inliers, point_inliers, line_inliers, rms, the numbers of point tracks and segment triplets,
pixel_scale, threshold and loss_scale (the estimate's tolerances in the images' pixels), and the
matched features as a problem (K.., R12, t12, points1..3, lines1..3, in undistorted pixels). With
--problem-only the matched problem is written without an estimate (tripose_estimate solves the file).
Images larger than --max-image-size (default 1600 px on the longer side; 0: no limit) are detected
in a reduced copy: the positions come back in the images' pixels, and the pixel tolerances
(--threshold among them) grow by the reduction.

Exit status: 0 on success, 1 on bad input (the message names the file, key or argument), 2 when the
tripose package (with its images extra: pip install "tripose[images]") is missing, 3 when no
reliable pose is found (fewer inliers than RansacOptions().min_inliers, 15); nothing is written on
1, 2 or 3.
"""
import argparse
import os
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np

MIN_FEATURES = 4  # the estimators need four features
# The refinement's Cauchy loss scale (px) for detected features, as the C++ samples
# (samples/common/image_estimation.hpp): it keeps the tail of poorly placed features from pulling.
IMAGE_LOSS_SCALE = 0.5


class InputError(Exception):
    pass


def whole_number(text):
    """An integer written as the C++ samples read one (1600, 1.6e3)."""
    value = float(text)
    if not value.is_integer():
        raise ValueError(text)
    return int(value)


class ArgumentParser(argparse.ArgumentParser):
    """Bad arguments are bad input: exit status 1, as the C++ samples (2 is the missing package's)."""

    def error(self, message):
        self.print_usage(sys.stderr)
        self.exit(1, f"{self.prog}: error: {message}\n")


def check_writable(path, option):
    """InputError naming option and path when the file cannot be written, checked before the work
    as the C++ samples do: an existing file must be writable, a new one is created and removed."""
    path = Path(path)
    if not path.parent.is_dir():
        raise InputError(f"{option} {path}: cannot be written (no folder {path.parent})")
    if path.is_dir():
        raise InputError(f"{option} {path}: cannot be written (a folder of that name exists)")
    if path.is_file():
        if not os.access(path, os.W_OK):
            raise InputError(f"{option} {path}: cannot be written (no permission)")
        return
    try:
        path.open("wb").close()
        path.unlink()
    except OSError:
        raise InputError(f"{option} {path}: cannot be written (no file can be created in {path.parent})") from None


def read_calibration(cv2, path):
    """K (three), dist (three or None), R12 (3x3), t12 (3x1) of a problem file's calibration keys."""
    fs = cv2.FileStorage(str(path), cv2.FILE_STORAGE_READ) if Path(path).is_file() else None
    if fs is None or not fs.isOpened():
        raise InputError(f"calibration {path}: cannot be read")

    def matrix(key):
        node = fs.getNode(key)
        return None if node.empty() else node.mat()

    def per_view(key, required):
        shared, views = matrix(key), [matrix(f"{key}{v}") for v in (1, 2, 3)]
        if shared is not None:
            return [shared] * 3
        if all(m is not None for m in views):
            return views
        if any(m is not None for m in views):
            raise InputError(f"calibration {path}: key '{key}{1 + [m is None for m in views].index(True)}': missing")
        if required:
            raise InputError(f"calibration {path}: key '{key}': missing (give {key} or {key}1..{key}3)")
        return None

    calib = {"K": per_view("K", True), "dist": per_view("dist", False)}
    for key, sizes in (("R12", (9, 3)), ("t12", (3,))):
        m = matrix(key)
        if m is None or m.size not in sizes:
            raise InputError(f"calibration {path}: key '{key}': " + ("missing" if m is None else "wrong size"))
        calib[key] = m
    fs.release()
    if calib["R12"].size == 3:
        calib["R12"] = cv2.Rodrigues(calib["R12"])[0]
    calib["t12"] = calib["t12"].reshape(3, 1)
    # Views 1 and 2 are matched under their epipolar geometry: checked before the features' time is spent.
    if not np.linalg.norm(calib["t12"]) > 0:
        raise InputError(f"calibration {path}: key 't12': must be non-zero (views 1 and 2 need a baseline)")
    return calib


def read_image(images, path, K, key):
    """The image as 8-bit grey (tripose.images.read_image), checked against the calibration's
    principal point: an image scaled against its calibration moves it a quarter of the image away."""
    try:
        image = images.read_image(path)
    except ValueError as e:
        raise InputError(str(e)) from None
    h, w = image.shape
    cx, cy = K[0, 2] / K[2, 2], K[1, 2] / K[2, 2]
    if abs(cx - w / 2) > 0.2 * w or abs(cy - h / 2) > 0.2 * h:
        raise InputError(f"image {path} is {w}x{h} but the principal point of {key} is ({cx:.1f}, {cy:.1f}): "
                         "the calibration is for another image size")
    return image


def write_result(cv2, path, calib, triplets, pose, tolerances):
    fs = cv2.FileStorage(str(path), cv2.FILE_STORAGE_WRITE)
    if not fs.isOpened():
        raise InputError(f"cannot write {path}")
    if pose is not None:
        fs.write("num_solutions", 1)
        fs.write("R", pose.R)
        fs.write("t", pose.t.reshape(3, 1))
        fs.write("rms", float(pose.rms))
        fs.write("num_inliers", int(pose.num_inliers))
        fs.write("point_inliers", pose.point_inliers.astype(np.int32).reshape(-1, 1))
        fs.write("line_inliers", pose.line_inliers.astype(np.int32).reshape(-1, 1))
    fs.write("num_point_tracks", len(triplets["points1"]))
    for key, value in tolerances.items():  # pixel_scale, and the estimate's in the images' pixels
        fs.write(key, float(value))
    fs.write("num_segment_triplets", len(triplets["lines1"]))
    for v in range(3):
        fs.write(f"K{v + 1}", calib["K"][v])
    fs.write("R12", calib["R12"])
    fs.write("t12", calib["t12"])
    for kind in ("points", "lines"):
        if len(triplets[f"{kind}1"]):
            for v in range(1, 4):
                fs.write(f"{kind}{v}", np.ascontiguousarray(triplets[f"{kind}{v}"], np.float64))
    fs.release()


def main(argv=None):
    parser = ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--calib", required=True)
    parser.add_argument("--images", nargs=3, required=True)
    parser.add_argument("--output", required=True)
    parser.add_argument("--features", choices=("points", "lines", "all"), default="all")
    parser.add_argument("--threshold", type=float, default=2.0)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--max-image-size", type=whole_number, default=1600,
                        help="detect features in images reduced to this longer side (px; 0: full size)")
    parser.add_argument("--problem-only", action="store_true", help="write the matched problem without an estimate")
    args = parser.parse_args(argv)
    if not args.threshold > 0:
        parser.error("argument --threshold: expected a positive number of pixels")
    if args.max_image_size < 0:
        parser.error("argument --max-image-size: expected 0 (full size) or a positive number of pixels")
    try:
        import cv2
        import tripose
        import tripose.images as images
    except ImportError as e:
        print(f"pose_from_images: {e} (pip install \"tripose[images]\")", file=sys.stderr)
        return 2
    try:
        check_writable(args.output, "--output")
        calib = read_calibration(cv2, args.calib)
        keys = ["K"] * 3 if calib["K"][0] is calib["K"][1] else ["K1", "K2", "K3"]
        grey = [read_image(images, p, calib["K"][v], keys[v]) for v, p in enumerate(args.images)]
        dist = calib["dist"] or [None] * 3
        feature_options = images.FeatureOptions(kinds=args.features, max_image_size=args.max_image_size)
        # One thread per image: OpenCV's detectors release the GIL, so the images share the cores.
        with ThreadPoolExecutor(max_workers=3) as pool:
            features = list(pool.map(lambda v: images.extract_features(grey[v], calib["K"][v], dist[v],
                                                                       feature_options), range(3)))
        # Features found in reduced images are that much less precise in the images' pixels: every
        # pixel tolerance, the matching's and the estimate's, grows by the reduction.
        pixel_scale = max(images.detection_scale(image.shape, args.max_image_size) for image in grey)
        reduction = (f"features detected in the images reduced by {pixel_scale:.2f} "
                     f"(--max-image-size {args.max_image_size})" if pixel_scale > 1 else "")
        if reduction:
            print(f"pose_from_images: {reduction}; pixel tolerances scaled by it")
        matching = tripose.MatchOptions()
        matching.epipolar_distance *= pixel_scale
        ransac = tripose.RansacOptions()  # refinement under the image front end's Cauchy loss
        ransac.threshold = args.threshold * pixel_scale
        ransac.refine_options.loss = "cauchy"
        ransac.refine_options.loss_scale = IMAGE_LOSS_SCALE * pixel_scale
        ransac.seed = args.seed & 0xFFFFFFFFFFFFFFFF  # a negative seed as the C++ tool's int
        floor, ransac.min_inliers = ransac.min_inliers, 0  # applied below, to report the best support
        tolerances = {"pixel_scale": pixel_scale, "threshold": ransac.threshold,
                      "loss_scale": ransac.refine_options.loss_scale}
        try:
            triplets = tripose.match_triplets(*features, calib["K"], calib["R12"], calib["t12"], matching)
        except (ValueError, TypeError) as e:
            raise InputError(f"the solver rejected the input of {args.calib}: {e}") from None
        # The most common calibration mistake, view 2's pose inverted (or the images in another
        # order), still yields matches and a wrong pose: matches found without the calibration tell it.
        matches, agreeing = triplets["pair_agreement"]
        if matches >= 20 and agreeing < 0.3 * matches:
            print(f"pose_from_images: warning: images 1 and 2 do not follow R12, t12 of {args.calib}: of {matches} "
                  f"point matches found without the poses, {agreeing} ({100 * agreeing / matches:.0f} %) lie on "
                  "their epipolar lines (73-88 % where the poses are right). Is [R12 | t12] view 2's pose in view "
                  "1's frame (x2 = R12 x1 + t12, not its inverse), and are the images in the calibration's order?",
                  file=sys.stderr)
        tracks, segments = len(triplets["points1"]), len(triplets["lines1"])
        print(f"pose_from_images: {tracks} point tracks, {segments} segment triplets")
        if tracks + segments < MIN_FEATURES:
            raise InputError(f"too few features seen in all three images ({', '.join(args.images)}): "
                             f"{tracks} point tracks and {segments} segment triplets"
                             + (f" ({reduction})" if reduction else ""))
        pose = None
        if not args.problem_only:
            try:
                pose = tripose.estimate_pose_line_point_ransac(
                    *(triplets[f"points{v}"] for v in (1, 2, 3)), *(triplets[f"lines{v}"] for v in (1, 2, 3)),
                    calib["K"], calib["R12"], calib["t12"], options=ransac)
            except (ValueError, TypeError) as e:
                raise InputError(f"the solver rejected the input of {args.calib}: {e}") from None
            if pose.R is None or pose.num_inliers < floor:
                print(f"pose_from_images: no reliable pose: {tracks} point tracks and {segments} segment triplets "
                      f"matched, {pose.num_inliers} inliers, fewer than the {floor} a pose needs; nothing written",
                      file=sys.stderr)
                return 3
            print(f"pose_from_images: {pose.num_inliers} inliers")
        write_result(cv2, args.output, calib, triplets, pose, tolerances)
    except InputError as e:
        print(f"pose_from_images: {e}", file=sys.stderr)
        return 1
    except ImportError as e:  # OpenCV without its contrib modules, found when first used
        print(f"pose_from_images: {e}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
