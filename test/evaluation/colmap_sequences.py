"""COLMAP's incremental structure from motion as the tracker's baseline (doc/studies/front_end_and_tracker.md,
"Against COLMAP"): each sequence reconstructed by pycolmap from its images with the sequence's intrinsics held
fixed, after sequential and after exhaustive matching, aligned to the ground truth as the tracker is (frame 0 at
the identity, the 0-1 baseline of the ground truth's length) and compared frame by frame.

    python test/evaluation/colmap_sequences.py [--sequences fountain_p11 ...] [--folders DIR ...] [--methods ...]
                                               [--output DIR] [--runs N] [--threads 1] [--seed 0]
                                               [--init-first-pair] [--mapper NAME=VALUE ...]

A folder holds a sequence in the tracker's layout: its images (an `images/` folder, or a list file
`images.txt`, `frames.txt` or `left.txt` (render_sequence.py's) as tripose-track --images reads it),
`calib.yml` (K, dist zero if any) and `groundtruth.txt` (TUM, one pose per frame, matched by timestamp,
else in order). With --output, one JSON file per sequence and
method holds every run's per-frame errors and aligned poses and the ground truth (plot_trajectories.py draws
them).
"""
import argparse
import json
import re
import shutil
import statistics
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(REPO / "test" / "python"))
import real_sequences as rs  # noqa: E402

SEQUENCES = ["fountain_p11", "herz_jesus_p8", "temple_ring", "kitti_06_forward", "model_house", "merton_college_1"]
METHODS = ["sequential", "exhaustive"]
IMAGE_SUFFIXES = {".png", ".jpg", ".jpeg", ".pgm", ".ppm", ".bmp", ".tif", ".tiff"}
# Sequential matching pairs each frame with this many following frames (no loop detection).
SEQUENTIAL_OVERLAP = 5


def import_pycolmap():
    """pycolmap, or an exit that says how to install it."""
    try:
        import pycolmap
    except ImportError:
        raise SystemExit("colmap_sequences.py needs pycolmap (pinned in requirements/python.txt): "
                         "pip install -r requirements/python.txt, or pip install pycolmap==4.2.1") from None
    return pycolmap


# --- sequences -------------------------------------------------------------------------------------

def _natural_key(path):
    return [int(part) if part.isdigit() else part.lower() for part in re.split(r"(\d+)", Path(path).name)]


def _read_image_list(path):
    """(timestamps or None, image paths) of an image list: a path per line, relative to the list's folder,
    optionally after a timestamp; blank lines and lines starting with # skipped."""
    stamps, images = [], []
    for number, line in enumerate(Path(path).read_text().splitlines(), 1):
        fields = line.split()
        if not fields or fields[0].startswith("#"):
            continue
        if len(fields) > 2:
            raise ValueError(f"folders: {path}:{number}: expected an image path, optionally after a timestamp")
        if len(fields) == 2:
            stamps.append(float(fields[0]))
        images.append(Path(path).parent / fields[-1])
    if stamps and len(stamps) != len(images):
        raise ValueError(f"folders: {path}: timestamps on some lines only")
    return (stamps or None), images


def _read_calibration_K(path):
    import cv2

    fs = cv2.FileStorage(str(path), cv2.FILE_STORAGE_READ)
    if not fs.isOpened():
        raise ValueError(f"folders: {path}: cannot be read")
    K = fs.getNode("K").mat()
    dist = fs.getNode("dist").mat()
    fs.release()
    if K is None or K.shape != (3, 3):
        raise ValueError(f"folders: {path}: no 3x3 K")
    if dist is not None and np.any(np.asarray(dist) != 0):
        raise ValueError(f"folders: {path}: a non-zero dist; the baseline takes undistorted images (a PINHOLE camera)")
    return np.asarray(K, np.float64)


def folder_sequence(folder):
    """The sequence of a folder in the tracker's layout, relative to its first frame."""
    folder = Path(folder)
    if (folder / "images").is_dir():
        images = sorted((p for p in (folder / "images").iterdir() if p.suffix.lower() in IMAGE_SUFFIXES),
                        key=_natural_key)
        stamps = None
    else:
        lists = [folder / name for name in ("images.txt", "frames.txt", "left.txt") if (folder / name).is_file()]
        if not lists:
            raise ValueError(f"folders: {folder}: neither an images/ folder nor an images.txt, frames.txt or "
                             "left.txt list")
        stamps, images = _read_image_list(lists[0])
    if len(images) < 2:
        raise ValueError(f"folders: {folder}: fewer than two images")
    K = _read_calibration_K(folder / "calib.yml")
    gt_stamps, gt_R, gt_t = rs.read_tum(folder / "groundtruth.txt")
    stamps = np.arange(len(images), dtype=np.float64) if stamps is None else np.asarray(stamps)
    order = []
    for s in stamps:
        k = int(np.argmin(np.abs(gt_stamps - s)))
        order.append(k if abs(gt_stamps[k] - s) <= 1e-6 * max(1.0, abs(s)) else None)
    if None in order:
        if len(gt_stamps) != len(images):
            raise ValueError(f"folders: {folder}/groundtruth.txt: {len(gt_stamps)} poses whose timestamps are not "
                             f"the {len(images)} frames'")
        order = list(range(len(images)))
    import cv2

    first = cv2.imread(str(images[0]), cv2.IMREAD_UNCHANGED)
    if first is None:
        raise ValueError(f"folders: {images[0]}: cannot be read")
    seq = rs.Sequence(folder.name, list(images), [K] * len(images), [gt_R[k] for k in order],
                      [gt_t[k] for k in order], first.shape[1], first.shape[0], [p.stem for p in images])
    return rs.relative_to_first(seq)


# --- COLMAP ----------------------------------------------------------------------------------------

def colmap_pinhole_params(K):
    """fx, fy, cx, cy of COLMAP's PINHOLE camera for K: COLMAP puts the first pixel's centre at (0.5, 0.5),
    the data sets at (0, 0)."""
    if abs(K[0, 1]) > 1e-9 * K[0, 0]:
        raise ValueError(f"K has a skew ({K[0, 1]}): COLMAP's PINHOLE camera has none")
    return [K[0, 0], K[1, 1], K[0, 2] + 0.5, K[1, 2] + 0.5]


def _without_skew(K):
    K = np.array(K, np.float64)
    K[0, 1] = 0.0
    return K


def extract(pycolmap, seq, work, threads):
    """A database with the frames' SIFT features (COLMAP's defaults on the CPU) and fixed PINHOLE cameras: one
    for the sequence when every frame has the same K, else one per frame; the images are linked as NNNN.ext
    in frame order (sequential matching orders images by name). COLMAP's PINHOLE camera has no skew: a frame
    whose K has one is written resampled by K' K^-1 (an affine map), K' being K without the skew, which is
    the same camera at the same pose."""
    import cv2

    one_camera = all(np.allclose(K, seq.K[0], rtol=1e-9, atol=1e-9) for K in seq.K)
    images = work / "images"
    images.mkdir()
    names, params = [], []
    for k, (path, K) in enumerate(zip(seq.image_paths, seq.K)):
        if abs(K[0, 1]) > 1e-9 * K[0, 0]:
            name = f"{k:04d}.png"
            image = cv2.imread(str(path), cv2.IMREAD_UNCHANGED)
            if image is None:
                raise ValueError(f"{seq.name}: {path} cannot be read")
            A = _without_skew(K) @ np.linalg.inv(K)
            cv2.imwrite(str(images / name), cv2.warpAffine(image, A[:2], (image.shape[1], image.shape[0]),
                                                           flags=cv2.INTER_CUBIC, borderMode=cv2.BORDER_REPLICATE))
        else:
            name = f"{k:04d}{Path(path).suffix.lower()}"
            (images / name).symlink_to(Path(path).resolve())
        names.append(name)
        params.append(colmap_pinhole_params(_without_skew(K)))
    database = work / "features.db"
    reader = pycolmap.ImageReaderOptions()
    reader.camera_model = "PINHOLE"
    reader.camera_params = ",".join(f"{v:.17g}" for v in params[0])
    extraction = pycolmap.FeatureExtractionOptions()
    extraction.num_threads = threads
    extraction.use_gpu = False
    start = time.perf_counter()
    mode = pycolmap.CameraMode.SINGLE if one_camera else pycolmap.CameraMode.PER_IMAGE
    pycolmap.extract_features(database, images, image_names=names, camera_mode=mode,
                              reader_options=reader, extraction_options=extraction, device=pycolmap.Device.cpu)
    if not one_camera:
        database_file = pycolmap.Database.open(database)
        for image in database_file.read_all_images():
            camera = database_file.read_camera(image.camera_id)
            camera.params = params[names.index(image.name)]
            camera.has_prior_focal_length = True
            database_file.update_camera(camera)
        database_file.close()
    return database, images, time.perf_counter() - start


def reconstruct(pycolmap, features, images, work, method, threads, seed, init_first_pair=False, mapper=()):
    """The largest reconstruction after `method` matching and incremental mapping with the intrinsics fixed,
    as {frame: (R, t)}, the number of reconstructions and the seconds taken. With `init_first_pair` the
    mapping starts from frames 0 and 1 (the tracker's start) instead of the pair COLMAP chooses; `mapper` is
    (name, value) pairs of IncrementalMapperOptions set after the defaults."""
    database = work / f"{method}.db"
    shutil.copyfile(features, database)
    pycolmap.set_random_seed(seed)
    matching = pycolmap.FeatureMatchingOptions()
    matching.num_threads = threads
    matching.use_gpu = False
    verification = pycolmap.TwoViewGeometryOptions()
    verification.ransac.random_seed = seed
    start = time.perf_counter()
    if method == "sequential":
        pairing = pycolmap.SequentialPairingOptions()
        pairing.overlap = SEQUENTIAL_OVERLAP
        pairing.quadratic_overlap = False
        pairing.loop_detection = False
        pairing.num_threads = threads
        pycolmap.match_sequential(database, matching_options=matching, pairing_options=pairing,
                                  verification_options=verification, device=pycolmap.Device.cpu)
    else:
        pycolmap.match_exhaustive(database, matching_options=matching, verification_options=verification,
                                  device=pycolmap.Device.cpu)
    options = pycolmap.IncrementalPipelineOptions()
    options.num_threads = threads
    options.random_seed = seed
    options.extract_colors = False
    options.ba_refine_focal_length = False
    options.ba_refine_principal_point = False
    options.ba_refine_extra_params = False
    options.mapper.abs_pose_refine_focal_length = False
    options.mapper.abs_pose_refine_extra_params = False
    for name, value in mapper:
        setattr(options.mapper, name, value)
    if init_first_pair:
        database_file = pycolmap.Database.open(database)
        ids = {int(Path(image.name).stem): image.image_id for image in database_file.read_all_images()}
        database_file.close()
        options.init_image_id1, options.init_image_id2 = ids[0], ids[1]
    output = work / f"{method}-sparse"
    output.mkdir()
    reconstructions = pycolmap.incremental_mapping(database, images, output, options=options)
    seconds = time.perf_counter() - start
    poses = {}
    if reconstructions:
        best = max(reconstructions.values(), key=lambda r: r.num_reg_images())
        for image in best.images.values():
            if image.has_pose:
                pose = image.cam_from_world()
                poses[int(Path(image.name).stem)] = (np.asarray(pose.rotation.matrix()),
                                                     np.asarray(pose.translation).reshape(3))
    return poses, len(reconstructions), seconds


def _mapper_defaults():
    return import_pycolmap().IncrementalMapperOptions()


# --- comparison ------------------------------------------------------------------------------------

def align_to_first(poses, seq):
    """The poses {frame: (R, t)} moved into frame 0's camera frame and scaled so that frame 1's centre is as
    far from frame 0's as in the ground truth `seq` (relative to its first frame): the tracker's frame. None
    without frames 0 and 1."""
    if 0 not in poses or 1 not in poses:
        return None
    R0, t0 = poses[0]
    relative = {k: rs.relative_pose(R0, t0, R, t) for k, (R, t) in poses.items()}
    baseline = np.linalg.norm(relative[1][1])
    if baseline == 0:
        return None
    scale = np.linalg.norm(rs.camera_centre(seq.R[1], seq.t[1])) / baseline
    return {k: (R, scale * t) for k, (R, t) in relative.items()}


def frame_errors(aligned, seq):
    """Per frame of `seq`: (rotation error deg, position error % of the ground-truth path), None for a frame
    without a pose."""
    path = rs.path_length(seq.R, seq.t)
    out = []
    for k in range(len(seq)):
        if aligned is None or k not in aligned:
            out.append(None)
        else:
            R, t = aligned[k]
            out.append((rs.rotation_error_deg(R, seq.R[k]),
                        100 * rs.position_error(R, t, seq.R[k], seq.t[k]) / path))
    return out


def summary(errors):
    """(frames with a pose, last frame's (deg, %) or None, largest (deg, %) or None)."""
    posed = [e for e in errors if e is not None]
    if not posed:
        return 0, None, None
    return len(posed), errors[-1], (max(e[0] for e in posed), max(e[1] for e in posed))


def _pose_json(R, t):
    return {"R": [float(v) for v in np.asarray(R).reshape(9)], "t": [float(v) for v in np.asarray(t).reshape(3)]}


def _spread(values, digits=3):
    values = sorted(values)
    text = f"{statistics.median(values):.{digits}f}"
    low, high = f"{values[0]:.{digits}f}", f"{values[-1]:.{digits}f}"
    return text + (f" ({low}-{high})" if low != high else "")


def report_row(label, seq, method, runs):
    """The table's row over the runs: the median and, with several runs, the range of each figure; a run that
    lost the last frame or frames 0-1 counts as 'lost' in the last frame's column."""
    registered = [r["registered"] for r in runs]
    lasts = [r["last"] for r in runs if r["last"] is not None]
    largest = [r["largest"] for r in runs if r["largest"] is not None]
    n = len(seq)
    reg = f"{statistics.median(registered):g}/{n}" + (f" ({min(registered)}-{max(registered)})"
                                                       if min(registered) != max(registered) else "")
    last = (f"{_spread([l[0] for l in lasts])} / {_spread([l[1] for l in lasts])}" if lasts else "lost")
    if lasts and len(lasts) < len(runs):
        last += f", lost in {len(runs) - len(lasts)} of {len(runs)}"
    big = f"{_spread([l[0] for l in largest])} / {_spread([l[1] for l in largest])}" if largest else "-"
    seconds = _spread([r["seconds"] / n for r in runs], 2)
    return f"| {label} | COLMAP {method} | {seq.width}x{seq.height} | {reg} | {last} | {big} | {seconds} |"


def evaluate(pycolmap, label, seq, args):
    """Every run of both methods on one sequence: the table's rows, and the JSON files under --output."""
    results = {m: [] for m in args.methods}
    with tempfile.TemporaryDirectory(prefix="colmap-") as tmp:
        tmp = Path(tmp)
        # SIFT extraction on the CPU is deterministic: the features are extracted once and their time
        # counted in every run of both methods.
        features, images, extract_seconds = extract(pycolmap, seq, tmp, args.threads)
        for run in range(args.runs):
            for method in args.methods:
                work = tmp / f"run{run}"
                work.mkdir(exist_ok=True)
                seed = args.seed + run
                poses, models, seconds = reconstruct(pycolmap, features, images, work, method, args.threads, seed,
                                                     args.init_first_pair, args.mapper)
                aligned = align_to_first(poses, seq)
                errors = frame_errors(aligned, seq)
                registered, last, largest = summary(errors)
                results[method].append({
                    "seed": seed, "reconstructions": models, "registered": len(poses),
                    "aligned": aligned is not None, "seconds": extract_seconds + seconds,
                    "seconds_extraction": extract_seconds, "seconds_matching_mapping": seconds,
                    "last": last, "largest": largest,
                    "frames": [{"frame": k, "id": str(seq.ids[k]) if seq.ids else str(k),
                                "registered": k in poses,
                                "rotation_deg": None if e is None else e[0],
                                "position_pct": None if e is None else e[1],
                                "pose": None if aligned is None or k not in aligned else _pose_json(*aligned[k])}
                               for k, e in enumerate(errors)]})
                print(f"  {label} {method} run {run + 1}/{args.runs}: {len(poses)}/{len(seq)} registered, "
                      + (f"last {last[0]:.3f} deg / {last[1]:.3f} %" if last else "last frame lost")
                      + f", {extract_seconds + seconds:.1f} s", file=sys.stderr, flush=True)
            shutil.rmtree(tmp / f"run{run}")
    changes = ", ".join(f"{name} {value:g}" for name, value in args.mapper)
    suffix = (", frames 0-1 first" if args.init_first_pair else "") + (f", {changes}" if changes else "")
    if args.output:
        args.output.mkdir(parents=True, exist_ok=True)
        for method, runs in results.items():
            tag = method + ("-first-pair" if args.init_first_pair else "") + ("-tuned" if args.mapper else "")
            lasts = [(r["last"][0], i) for i, r in enumerate(runs) if r["last"] is not None]
            document = {
                "sequence": label, "name": seq.name, "method": f"colmap-{tag}",
                "pycolmap": pycolmap.__version__, "image_size": [seq.width, seq.height],
                "options": {"init_first_pair": args.init_first_pair, "mapper": dict(args.mapper),
                            "threads": args.threads, "sequential_overlap": SEQUENTIAL_OVERLAP},
                "path_length": rs.path_length(seq.R, seq.t),
                "groundtruth": [_pose_json(R, t) for R, t in zip(seq.R, seq.t)],
                "median_run": sorted(lasts)[(len(lasts) - 1) // 2][1] if lasts else 0,
                "runs": runs}
            (args.output / f"{label}-colmap-{tag}.json").write_text(json.dumps(document, indent=1) + "\n")
    return [report_row(label, seq, m + suffix, results[m]) for m in args.methods]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sequences", nargs="*", default=None, choices=SEQUENCES,
                        help="real sequences (default: the first four unless --folders is given)")
    parser.add_argument("--folders", nargs="+", type=Path, default=[], help="sequences in the tracker's layout")
    parser.add_argument("--methods", nargs="+", default=METHODS, choices=METHODS, help="matching (default both)")
    parser.add_argument("--output", type=Path, help="folder for the per-frame JSON files")
    parser.add_argument("--runs", type=int, default=1, help="reconstructions per method (seeds seed..seed+N-1)")
    parser.add_argument("--threads", type=int, default=1, help="COLMAP's threads (default 1)")
    parser.add_argument("--seed", type=int, default=0, help="the first run's random seed")
    parser.add_argument("--init-first-pair", action="store_true",
                        help="start the mapping from frames 0 and 1, as the tracker does (default: COLMAP's choice)")
    parser.add_argument("--mapper", nargs="+", default=[], metavar="NAME=VALUE",
                        help="IncrementalMapperOptions changed from COLMAP's defaults, e.g. init_min_tri_angle=4")
    args = parser.parse_args()
    mapper = []
    defaults = _mapper_defaults() if args.mapper else None
    for item in args.mapper:
        name, sep, value = item.partition("=")
        if not sep or name.startswith("_") or not hasattr(defaults, name):
            parser.error(f"--mapper: {item!r} is not NAME=VALUE with a name of IncrementalMapperOptions")
        default = getattr(defaults, name)
        if not isinstance(default, (bool, int, float)):
            parser.error(f"--mapper: {name} is not a number option")
        try:
            mapper.append((name, value == "1" if isinstance(default, bool) else type(default)(float(value))))
        except ValueError:
            parser.error(f"--mapper: {item!r}: {value!r} is not a number")
    args.mapper = mapper
    if args.runs < 1:
        parser.error(f"--runs must be at least 1, got {args.runs}")
    if args.threads < 1:
        parser.error(f"--threads must be at least 1, got {args.threads}")
    pycolmap = import_pycolmap()
    pycolmap.logging.minloglevel = 2
    sequences = args.sequences if args.sequences is not None else ([] if args.folders else SEQUENCES[:4])
    jobs = [(name, lambda name=name: rs.relative_to_first(getattr(rs, name)())) for name in sequences]
    jobs += [(folder.name, lambda folder=folder: folder_sequence(folder)) for folder in args.folders]
    rows = []
    for label, load in jobs:
        try:
            seq = load()
        except ValueError as error:
            parser.error(str(error))
        rows += evaluate(pycolmap, label, seq, args)
    print(f"\nCOLMAP (pycolmap {pycolmap.__version__}, {args.runs} run(s), median (range)): sequence | method | "
          "image size | frames with a pose | last frame deg / % path | largest deg / % | s per frame")
    print("|---|---|---|---|---|---|---|")
    print("\n".join(rows))


if __name__ == "__main__":
    main()
