#!/usr/bin/env python3
"""Writes the seed corpora of the fuzz targets into test/fuzz/corpus/<target>/.

Seeds are small valid problems: scenes from the project's generator (tripose_make_scene of a
standalone build) and three views of Oxford VGG's Merton College I (test/data/vgg), the first
features seen in all three views, with intrinsics and poses from the sequence's projection matrices.

  fuzz_problem_reader: the problem file text (YAML or JSON).
  fuzz_estimate_pose:  the binary layout documented at the top of fuzz_estimate_pose.cpp.

  .venv/bin/python test/fuzz/make_corpus.py [--build build]
"""
import argparse
import struct
import subprocess
import tempfile
from pathlib import Path

import cv2
import numpy as np

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]
KEYS = ["K1", "K2", "K3", "R12", "t12", "points1", "points2", "points3", "lines1", "lines2", "lines3"]
STEREO_KEYS = ["K1", "K2", "K3", "K4", "R12", "t12", "points1", "points2", "points3", "points4",
               "lines1", "lines2", "lines3", "lines4"]


def generated_scene(tool, points, lines, seed, noise, outliers):
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "scene.yml"
        subprocess.run([str(tool), "--points", str(points), "--lines", str(lines), "--noise", str(noise),
                        "--outliers", str(outliers), "--seed", str(seed), "--output", str(out)],
                       check=True, capture_output=True)
        fs = cv2.FileStorage(str(out), cv2.FILE_STORAGE_READ)
        problem = {k: fs.getNode(k).mat() for k in KEYS if not fs.getNode(k).empty()}
        fs.release()
    return {k: v for k, v in problem.items() if v is not None and v.size > 0}


def generated_stereo_scene(tool, points, lines, seed, missing):
    """A stereo-rig problem (tripose_make_scene --stereo): rows of NaN where a time-B view does not see."""
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "rig.yml"
        subprocess.run([str(tool), "--stereo", "--points", str(points), "--lines", str(lines), "--missing",
                        str(missing), "--seed", str(seed), "--output", str(out)], check=True, capture_output=True)
        fs = cv2.FileStorage(str(out), cv2.FILE_STORAGE_READ)
        problem = {k: fs.getNode(k).mat() for k in STEREO_KEYS if not fs.getNode(k).empty()}
        fs.release()
    return problem


def read_rows(path):
    return [line.split() for line in Path(path).read_text().splitlines() if line.strip()]


def vgg_problem(count):
    """Views 001-003 of Merton College I: the first `count` points and lines seen in all three."""
    folder = REPO / "test" / "data" / "vgg" / "Merton-College-I"
    Ks, Rs, ts = [], [], []
    for view in ("001", "002", "003"):
        P = np.loadtxt(folder / f"{view}.P")
        K, R, C = cv2.decomposeProjectionMatrix(P)[:3]
        D = np.diag(np.sign(np.diag(K)))          # positive focal lengths
        K, R = K @ D, D @ R
        if np.linalg.det(R) < 0:                  # P was given with a negative scale
            R = -R
        C = C[:3] / C[3]
        Ks.append(K / K[2, 2])
        Rs.append(R)
        ts.append(-R @ C)
    R12 = Rs[1] @ Rs[0].T
    t12 = ts[1] - R12 @ ts[0]
    problem = {"K1": Ks[0], "K2": Ks[1], "K3": Ks[2], "R12": R12, "t12": t12}
    for kind, suffix, width in (("points", "corners", 2), ("lines", "lines", 4)):
        tracks = [r for r in read_rows(folder / f"nview-{kind if kind == 'lines' else 'corners'}")
                  if "*" not in r[:3]][:count]
        for v, view in enumerate(("001", "002", "003")):
            observations = np.loadtxt(folder / f"{view}.{suffix}").reshape(-1, width)
            problem[f"{kind}{v + 1}"] = np.array([observations[int(r[v])] for r in tracks])
    # The relative pose of view 3, for seeds that start the refinement from it.
    problem["_R13"] = Rs[2] @ Rs[0].T
    problem["_t13"] = ts[2] - problem["_R13"] @ ts[0]
    return problem


def problem_text(problem, suffix, keys=KEYS):
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / f"problem{suffix}"
        fs = cv2.FileStorage(str(path), cv2.FILE_STORAGE_WRITE)
        for key in keys:
            if key in problem:
                fs.write(key, np.asarray(problem[key], dtype=np.float64))
        fs.release()
        return path.read_bytes()


def encode(problem, options, initial=None):
    """The fuzz_estimate_pose layout; options as there (bits 0, 2, 3, 4, 7 are honoured here)."""
    def doubles(values):
        return b"".join(struct.pack("<d", float(x)) for x in np.asarray(values, dtype=np.float64).ravel())

    n = len(problem.get("points1", []))
    m = len(problem.get("lines1", []))
    out = bytes([n, m, options, 1, 15, 5]) + doubles([2.0, 0.99, 1.0, 1e-10])
    Ks = [problem["K1"], problem["K2"], problem["K3"]] if options & 4 else [problem["K1"]]
    out += b"".join(doubles(K) for K in Ks)
    if options & 8:
        out += b"".join(doubles([1e-3, 0, 0, 0, 0]) for _ in Ks)
    out += doubles(cv2.Rodrigues(problem["R12"])[0] if options & 16 else problem["R12"]) + doubles(problem["t12"])
    if options & 128:
        out += doubles(cv2.Rodrigues(initial[0])[0]) + doubles(initial[1])
    for v in range(3):
        out += doubles(problem.get(f"points{v + 1}", np.zeros((0, 2))))
    for v in range(3):
        lines = problem.get(f"lines{v + 1}", np.zeros((0, 4)))
        if options & 1:  # homogeneous lines through the two end points
            lines = np.array([np.cross([x0, y0, 1.0], [x1, y1, 1.0]) for x0, y0, x1, y1 in lines]).reshape(-1, 3)
        out += doubles(lines)
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", default=str(REPO / "build"), help="standalone build with samples/tripose_make_scene")
    args = parser.parse_args()
    tool = Path(args.build) / "samples" / "tripose_make_scene"

    scenes = {
        "scene_3p3l": generated_scene(tool, 3, 3, seed=1, noise=0.0, outliers=0.0),
        "scene_4p0l": generated_scene(tool, 4, 0, seed=2, noise=0.0, outliers=0.0),
        "scene_0p5l": generated_scene(tool, 0, 5, seed=3, noise=0.0, outliers=0.0),
        "scene_8p6l_noisy": generated_scene(tool, 8, 6, seed=4, noise=1.0, outliers=0.25),
    }
    vgg = vgg_problem(6)
    scenes["vgg_merton1_6p6l"] = {k: v for k, v in vgg.items() if not k.startswith("_")}

    reader = HERE / "corpus" / "fuzz_problem_reader"
    api = HERE / "corpus" / "fuzz_estimate_pose"
    for folder in (reader, api):
        folder.mkdir(parents=True, exist_ok=True)
        for old in folder.iterdir():
            old.unlink()
    for name, problem in scenes.items():
        (reader / f"{name}.yml.seed").write_bytes(problem_text(problem, ".yml"))
    for name in ("scene_3p3l", "vgg_merton1_6p6l"):
        (reader / f"{name}.json.seed").write_bytes(problem_text(scenes[name], ".json"))
    rig = generated_stereo_scene(tool, 6, 4, seed=5, missing=0.5)
    (reader / "stereo_6p4l_missing.yml.seed").write_bytes(problem_text(rig, ".yml", STEREO_KEYS))
    (reader / "stereo_6p4l_missing.json.seed").write_bytes(problem_text(rig, ".json", STEREO_KEYS))

    # Options: 96 = local optimisation + refinement; 2 float32; 4 three K; 16 Rodrigues R12;
    # 1 homogeneous lines; 8 distortion; 128 initial pose for the refinement.
    (api / "scene_3p3l").write_bytes(encode(scenes["scene_3p3l"], 96))
    (api / "scene_4p0l_f32_threeK_rodrigues").write_bytes(encode(scenes["scene_4p0l"], 96 | 2 | 4 | 16))
    (api / "scene_0p5l_homogeneous").write_bytes(encode(scenes["scene_0p5l"], 1))
    (api / "scene_8p6l_noisy_distortion").write_bytes(encode(scenes["scene_8p6l_noisy"], 96 | 8))
    (api / "vgg_merton1_6p6l_threeK_initial").write_bytes(
        encode(scenes["vgg_merton1_6p6l"], 96 | 4 | 128, (vgg["_R13"], vgg["_t13"])))


if __name__ == "__main__":
    main()
