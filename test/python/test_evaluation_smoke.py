# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.

"""The evaluation suite (test/evaluation/run_evaluation.py) at its smoke size, into a temporary folder.

Runs every experiment of doc/studies/evaluation.md with few trials (well under 3 minutes on 2 cores) and
checks what must hold whatever the machine: every artefact is written, noise-free problems are
solved to rounding error, errors grow with the noise, the maximum-likelihood estimate is at least
as accurate as the linear solver it starts from, RANSAC survives outliers that break the linear
solver (20 points + 20 lines and 3 points + 60 lines), and the stereo rig's RANSAC stays near the
four-view limit with and without outliers. A tripose_evaluate that has not been built
($TRIPOSE_BUILD_DIR or build/) is an error.
"""

import json
import subprocess
import sys

import numpy as np
import pytest

from tripose_tools import REPO, build_tool, require_modules

DRIVER = REPO / "test" / "evaluation" / "run_evaluation.py"


@pytest.fixture(scope="module")
def smoke(tmp_path_factory):
    build_tool("tripose_evaluate", folder="test/evaluation")
    require_modules("poselib", "matplotlib", "tqdm")
    out = tmp_path_factory.mktemp("evaluation")
    subprocess.run([sys.executable, str(DRIVER), "--size", "smoke", "--out", str(out)], check=True,
                   stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=600)
    summary = json.loads((out / "data" / "summary.json").read_text())
    return out, summary["results"]


def _groups(results, name, **match):
    return [g for g in results[name] if all(g["key"].get(k) == v for k, v in match.items())]


def test_every_artefact_is_written(smoke):
    out, results = smoke
    assert set(results) == {"fig3", "fig4", "fig5", "fig6", "outliers", "regimes", "stereo"}
    expected = ["fig3_large", "fig3_small", "fig4_large", "fig4_small", "fig5_time", "outliers", "regimes", "stereo"]
    expected += [f"fig6_{s}" for s in ("University-Library", "Merton-College-I", "Merton-College-II",
                                       "Merton-College-III", "Wadham-College", "Corridor", "Model-House")]
    for name in expected:
        png = out / f"{name}.png"
        assert png.is_file() and png.stat().st_size > 10_000, name
    tables = (out / "tables.md").read_text()
    for heading in ("Fig. 3", "Fig. 4", "Fig. 5", "Fig. 6", "Outliers", "narrow 1 %", "narrow 0.5 %", "planar large",
                    "planar small", "Stereo rig"):
        assert heading in tables


def test_noise_free_problems_are_solved_exactly(smoke):
    _, results = smoke
    for name in ("fig3", "fig4"):
        groups = _groups(results, name, noise=0.0)
        assert groups, name
        for g in groups:
            s = g["methods"]["linear"]
            # Median over the trials: a single near-degenerate draw must not hide a systematic error.
            assert s["fails"] == 0, g["key"]
            assert s["rot_deg"]["median"] < 1e-6, g["key"]
            assert s["t_rel"]["median"] < 1e-8, g["key"]


def test_errors_grow_with_noise(smoke):
    _, results = smoke
    for motion in ("large", "small"):
        for method in ("linear", "ml_from_truth"):
            for n in (4, 8):
                medians = [g["methods"][method]["rot_deg"]["median"]
                           for g in sorted(_groups(results, "fig4", motion=motion, points=n), key=lambda g: g["key"]["noise"])]
                assert medians == sorted(medians), (motion, method, n, medians)
                assert medians[-1] > 100 * max(medians[0], 1e-12), (motion, method, n, medians)


def test_maximum_likelihood_is_at_least_as_accurate_as_linear(smoke):
    _, results = smoke
    # Pooled over the noisy Fig. 4 groups: the ML estimate uses the noise model the linear solver
    # ignores, so its median errors must not be larger overall (20 trials per group: compare sums).
    for quantity in ("rot_deg", "t_rel"):
        ml = linear = 0.0
        for g in results["fig4"]:
            if g["key"]["noise"] > 0:
                ml += g["methods"]["ml_from_truth"][quantity]["median"]
                linear += g["methods"]["linear"][quantity]["median"]
        assert linear > 0, (quantity, "no noisy Fig. 4 group")
        assert ml <= linear, (quantity, ml, linear)


def test_ransac_survives_outliers_that_break_the_linear_solver(smoke):
    _, results = smoke
    assert {g["key"]["config"] for g in results["outliers"]} == {"20P+20L", "3P+60L", "rig 100P+40L"}
    # 20 points + 20 lines and the line-heavy 3 points + 60 lines: RANSAC + refine stays near the
    # truth where 30 % wrong matches in view 3 throw the linear solver degrees off (full run, 10-60 %
    # wrong matches: 6-96 degrees for the linear solver, under 0.3 for RANSAC + refine).
    for config in ("20P+20L", "3P+60L"):
        g = _groups(results, "outliers", config=config, outliers=0.3)[0]
        ours, linear = g["methods"]["ransac"]["rot_deg"]["median"], g["methods"]["linear"]["rot_deg"]["median"]
        assert ours < 1.0, config
        assert g["methods"]["ransac"]["t_rel"]["median"] < 0.02, config
        assert linear > 5.0, config
        assert "poselib-adaptive" in g["methods"], config


def test_rig_ransac_stays_near_the_four_view_limit_under_outliers(smoke):
    _, results = smoke
    for ratio in (0.0, 0.3):
        g = _groups(results, "outliers", config="rig 100P+40L", outliers=ratio)[0]
        methods = g["methods"]
        assert {"stereo_ransac", "stereo_ml_from_truth", "poselib-generalized"} <= set(methods), ratio
        # The limit is refined from the truth on the true matches, so outliers hardly move it (0.053 and
        # 0.067 degrees in the full run, where the stereo RANSAC's median is 1.01x and 1.03x it).
        limit = methods["stereo_ml_from_truth"]["rot_deg"]["median"]
        assert limit < 0.2, ratio
        assert methods["stereo_ransac"]["fails"] == 0, ratio
        assert methods["stereo_ransac"]["rot_deg"]["median"] <= 1.5 * limit, ratio


def test_vgg_sequences_give_accurate_poses_with_ten_of_each(smoke):
    _, results = smoke
    groups = _groups(results, "fig6", lines=10, points=10)
    assert len(groups) == 7
    for g in groups:
        assert g["methods"]["ransac"]["rot_deg"]["median"] < 2.0, g["key"]
        assert g["methods"]["ml_from_truth"]["rot_deg"]["median"] < 2.0, g["key"]


def test_regimes_cover_every_method_and_refinement_helps(smoke):
    _, results = smoke
    assert {g["key"]["regime"] for g in results["regimes"]} == {"narrow 1 %", "narrow 0.5 %", "planar large",
                                                               "planar small"}
    # Each regime has the 10-point group whose accuracy is checked below.
    assert {g["key"]["regime"] for g in results["regimes"] if g["key"]["points"] == 10} == \
        {g["key"]["regime"] for g in results["regimes"]}
    for g in results["regimes"]:
        methods = g["methods"]
        for key in ("linear", "linear+refine", "ransac", "ml_from_truth", "tri+sqpnp", "poselib"):
            assert key in methods, (g["key"], key)
        if g["key"]["points"] != 10:
            continue
        ours = methods["ransac"]["rot_deg"]["median"]
        if g["key"]["regime"].startswith("planar"):
            # Planar structure: RANSAC + refine reaches the ML optimum in every scene of the study in
            # doc/studies/accuracy.md (100 scenes); 1.5x leaves room for 10 smoke scenes.
            assert ours <= 1.5 * methods["ml_from_truth"]["rot_deg"]["median"] + 1e-3, g["key"]
        else:
            # Narrow pair: triangulating from it is the weak step of the peers (5-7 deg at 1 px in
            # the smoke run, against about 1 deg), which refinement in all three views avoids.
            assert ours <= 0.5 * methods["tri+sqpnp"]["rot_deg"]["median"], g["key"]


def test_stereo_covers_every_method_and_the_right_image_helps(smoke):
    _, results = smoke
    assert {(g["key"]["points"], g["key"]["noise"]) for g in results["stereo"]} == {(4, 1.0), (10, 1.0)}
    for g in results["stereo"]:
        methods = g["methods"]
        for key in ("stereo_linear", "stereo_multi_start", "stereo_linear+refine", "stereo_ransac",
                    "stereo_ml_from_truth", "three_view_ransac", "three_view_linear+refine", "tri+sqpnp", "poselib"):
            assert key in methods, (g["key"], key)
        assert ("tri+iterative" in methods) == (g["key"]["points"] >= 6), g["key"]
        if g["key"]["points"] != 10:
            continue
        # Ten scenes only: loose bounds that the full run's 500 scenes per setting meet by far
        # (doc/studies/evaluation.md, Stereo rig): near the four-view limit, and the right image at B helps.
        limit = methods["stereo_ml_from_truth"]["rot_deg"]["median"]
        ours = methods["stereo_ransac"]["rot_deg"]["median"]
        assert ours <= 1.5 * limit, g["key"]
        assert ours < methods["three_view_ransac"]["rot_deg"]["median"], g["key"]


def test_dumped_rig_scenes_mark_their_true_matches():
    """--dump-inputs writes which matches are true: without noise a true point's view-3 observation is
    the projection of its structure from the rig at time A, and a wrong one lies at least 20 px away."""
    tool = build_tool("tripose_evaluate", folder="test/evaluation")
    out = subprocess.run([str(tool), "stereo", "--points", "20", "--lines", "10", "--noise", "0", "--outliers", "0.5",
                          "--trials", "3", "--methods", "stereo_ransac", "--dump-inputs"],
                         check=True, capture_output=True, text=True, timeout=120).stdout
    scenes = [json.loads(line)["rig_inputs"] for line in out.splitlines()]
    assert len(scenes) == 3
    for s in scenes:
        true_points = np.array(s["true_point_matches"][0]) == 1
        true_lines = np.array(s["true_line_matches"][0]) == 1
        assert true_points.shape == (20,) and true_points.sum() == 10
        assert true_lines.shape == (10,) and true_lines.sum() == 5
        K = np.array(s["K"][2])
        R, t = np.array(s["R_gt"]), np.array(s["t_gt"]).reshape(3)
        X = np.array(s["points3d_12"])
        x3 = np.array(s["points3"], dtype=float)
        projected = (K @ (X @ R.T + t).T).T
        error = np.linalg.norm(projected[:, :2] / projected[:, 2:] - x3, axis=1)
        seen = np.isfinite(error)
        assert seen.sum() >= 10
        assert np.all(error[seen & true_points] < 1e-6)
        assert np.all(error[seen & ~true_points] > 19.0)
