"""Per-frame errors and trajectories of the tracker and of COLMAP, one PNG per sequence
(doc/studies/front_end_and_tracker.md, "Against COLMAP"): rotation error and position error per frame for each
method, and a top view of the trajectories with the ground truth.

    python test/evaluation/plot_trajectories.py --colmap DIR_OR_JSON ... [--tripose SEQUENCE=TUM ...]
                                                [--fps F] --output DIR [--prefix against-colmap-]

--colmap takes colmap_sequences.py's JSON files (or folders of them); each file's median run is drawn, its other
runs faintly. --tripose takes a TUM trajectory of the tracker (track_real_sequences.py --trajectories), frames
stamped by index (or, with --fps, by time: frame = stamp x fps; frames past the sequence's last one, as in a
longer run of the same images, are left out), for the sequence named before the '=' (a name of the JSON files'
"sequence"); it is aligned
as COLMAP's is (frame 0 at the identity, the ground truth's 0-1 baseline), which leaves the tracker's own
trajectory unchanged when frames 0-1 were given from the ground truth.
"""
import argparse
import json
import sys
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(REPO / "test" / "python"))
sys.path.insert(0, str(REPO / "test" / "evaluation"))
import real_sequences as rs  # noqa: E402
from colmap_sequences import align_to_first, frame_errors  # noqa: E402

# Colour and marker of COLMAP's methods: [0] with COLMAP's defaults, [1] with the options changed.
STYLE = {"sequential": (("tab:orange", "s"), ("tab:brown", "D")),
         "exhaustive": (("tab:green", "^"), ("tab:olive", "v"))}
TRIPOSE_COLOURS = ["tab:blue", "tab:purple", "tab:cyan"]


def _pose(entry):
    return np.array(entry["R"]).reshape(3, 3), np.array(entry["t"])


def groundtruth(document):
    """The ground truth of a JSON file as a Sequence (relative to its first frame)."""
    Rs, ts = zip(*(_pose(p) for p in document["groundtruth"]))
    n = len(Rs)
    return rs.Sequence(document["name"], [None] * n, [None] * n, list(Rs), list(ts), *document["image_size"])


def run_curves(run):
    """(rotation deg, position %, centres) per frame of a JSON run, NaN where the frame has no pose."""
    rot = np.array([np.nan if f["rotation_deg"] is None else f["rotation_deg"] for f in run["frames"]])
    pos = np.array([np.nan if f["position_pct"] is None else f["position_pct"] for f in run["frames"]])
    centres = np.array([[np.nan] * 3 if f["pose"] is None else rs.camera_centre(*_pose(f["pose"]))
                        for f in run["frames"]])
    return rot, pos, centres


def tripose_curves(path, seq, fps=1.0):
    """The curves of a tracker's TUM trajectory against the ground truth `seq`, frame round(stamp x fps)."""
    stamps, Rs, ts = rs.read_tum(path)
    poses = {int(round(s * fps)): (R, t) for s, R, t in zip(stamps, Rs, ts)}
    if any(k < 0 for k in poses):
        raise ValueError(f"tripose: {path}: negative frame stamps")
    poses = {k: pose for k, pose in poses.items() if k < len(seq)}
    aligned = align_to_first(poses, seq)
    errors = frame_errors(aligned, seq)
    rot = np.array([np.nan if e is None else e[0] for e in errors])
    pos = np.array([np.nan if e is None else e[1] for e in errors])
    centres = np.array([[np.nan] * 3 if aligned is None or k not in aligned else rs.camera_centre(*aligned[k])
                        for k in range(len(seq))])
    return rot, pos, centres


def top_view_axes(seq):
    """Two axes of a top view: the plane of the ground-truth centres when they span one (an arc, a ring), else
    the plane normal to the mean of the cameras' -y axes (level cameras) with frame 0's x made horizontal.
    Seen from the side the cameras' -y axes point to."""
    up = np.mean([-np.asarray(R)[1] for R in seq.R], axis=0)
    up /= np.linalg.norm(up)
    centres = seq.centres()
    _, sv, Vt = np.linalg.svd(centres - centres.mean(axis=0))
    if len(centres) >= 3 and sv[1] > 0.1 * sv[0]:
        normal = Vt[2] if np.dot(Vt[2], up) >= 0 else -Vt[2]
        e1 = Vt[0]
    else:
        normal = up
        e1 = np.array([1.0, 0.0, 0.0]) - up[0] * up
    e1 = e1 / np.linalg.norm(e1)
    return e1, np.cross(normal, e1)


def method_style(method):
    """The colour and marker of a COLMAP method name (colmap-<sequential|exhaustive>[-first-pair][-tuned])."""
    base = "exhaustive" if "exhaustive" in method else "sequential"
    return STYLE[base][int(method != f"colmap-{base}")]


def method_name(document):
    """The legend's name of a JSON file's method, with the options changed from COLMAP's defaults."""
    base = "exhaustive" if "exhaustive" in document["method"] else "sequential"
    options = document.get("options", {})
    mapper = options.get("mapper", {})
    changes = ([] if not mapper else ["initial pair relaxed"] if all(k.startswith("init_") for k in mapper)
               else ["mapper options changed"])
    if options.get("init_first_pair"):
        changes.insert(0, "frames 0-1 first")
    return f"COLMAP {base}" + (f" ({', '.join(changes)})" if changes else "")


def summary_line(name, rot, pos):
    """A curve's last frame's and largest errors, as the study's table gives them (its name counts its frames)."""
    found = np.isfinite(rot)
    last = f"{rot[-1]:.3f} / {pos[-1]:.3f}" if found[-1] else "lost"
    largest = f"{np.nanmax(rot):.3f} / {np.nanmax(pos):.3f}" if found.any() else "-"
    return f"  {name}: last {last}, largest {largest} (deg / % path)"


def plot_sequence(label, documents, tripose, output, prefix, fps=1.0):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    seq = groundtruth(documents[0])
    n = len(seq)
    frames = np.arange(n)
    e1, e2 = top_view_axes(seq)
    fig, (ax_r, ax_p, ax_t) = plt.subplots(1, 3, figsize=(13, 4.4), gridspec_kw={"width_ratios": [1, 1, 1.1]})
    gt = seq.centres()
    ax_t.plot(gt @ e1, gt @ e2, "-", color="black", lw=2.5, alpha=0.35, label="ground truth")
    ax_t.plot([gt[0] @ e1], [gt[0] @ e2], "o", color="black")
    curves = []
    for document in documents:
        colour, marker = method_style(document["method"])
        median = document["median_run"]
        for i, run in enumerate(document["runs"]):
            rot, pos, centres = run_curves(run)
            if i == median:
                registered = int(np.sum(np.isfinite(rot)))
                name = method_name(document)
                curves.append((f"{name}: {registered}/{n}, run {i + 1} of {len(document['runs'])}",
                               colour, marker, rot, pos, centres, 1.0))
            else:
                curves.append((None, colour, None, rot, pos, centres, 0.25))
    for (name, path), colour in zip(tripose, TRIPOSE_COLOURS):
        rot, pos, centres = tripose_curves(path, seq, fps)
        curves.append((f"{name}: {int(np.sum(np.isfinite(rot)))}/{n}", colour, "o", rot, pos, centres, 1.0))
    for name, colour, marker, rot, pos, centres, alpha in curves:
        if name:
            print(summary_line(name, rot, pos))
        size = 4 if n > 20 else 5
        ax_r.plot(frames, rot, "-", color=colour, marker=marker, ms=size, alpha=alpha, label=name)
        ax_p.plot(frames, pos, "-", color=colour, marker=marker, ms=size, alpha=alpha, label=name)
        ax_t.plot(centres @ e1, centres @ e2, "-", color=colour, marker=marker, ms=size - 1, alpha=alpha)
    ax_r.set(xlabel="frame", ylabel="rotation error (deg)", title="rotation")
    ax_p.set(xlabel="frame", ylabel="position error (% of path)", title="position")
    ax_t.set(xlabel="m", ylabel="m", title="top view")
    ax_t.set_aspect("equal", adjustable="datalim")
    for ax in (ax_r, ax_p):
        ax.set_ylim(bottom=0)
        ax.grid(alpha=0.3)
        if n <= 12:
            ax.set_xticks(frames)
    ax_t.grid(alpha=0.3)
    handles, labels = ax_r.get_legend_handles_labels()
    gt_handle, gt_label = ax_t.get_legend_handles_labels()
    fig.legend(gt_handle + handles, gt_label + labels, loc="lower center", ncol=3, fontsize=8, frameon=False)
    fig.suptitle(f"{seq.name}: frames 0-1 aligned to the ground truth", fontsize=10)
    rows = (len(handles) + 1 + 2) // 3
    fig.tight_layout(rect=(0, 0.06 * rows, 1, 1))
    output.mkdir(parents=True, exist_ok=True)
    path = output / f"{prefix}{label}.png"
    fig.savefig(path, dpi=80)
    plt.close(fig)
    return path


def tripose_label(sequence, path):
    """The legend's name of a tracker trajectory from track_real_sequences.py's file name
    (<sequence>-cpp.txt: tripose_track, <sequence>-python.txt: tripose-track), else the file's name."""
    program = path.stem[len(sequence) + 1:] if path.stem.startswith(sequence + "-") else None
    return {"cpp": "tripose_track (C++)", "python": "tripose-track (Python)"}.get(program, f"tripose ({path.name})")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--colmap", nargs="+", type=Path, required=True, help="JSON files or folders of them")
    parser.add_argument("--tripose", nargs="*", default=[], metavar="SEQUENCE=TUM",
                        help="the tracker's trajectory of a sequence; repeat a sequence for several programs")
    parser.add_argument("--label", nargs="*", default=None,
                        help="a legend label per --tripose file (default: from track_real_sequences.py's file names)")
    parser.add_argument("--fps", type=float, default=1.0,
                        help="--tripose stamps are times at this frame rate (default 1: frame indices)")
    parser.add_argument("--output", type=Path, required=True)
    parser.add_argument("--prefix", default="", help="prefix of the PNG file names")
    args = parser.parse_args()
    if not args.fps > 0:
        parser.error(f"--fps must be positive, got {args.fps}")
    files = []
    for path in args.colmap:
        files += sorted(path.glob("*.json")) if path.is_dir() else [path]
    if not files:
        parser.error("--colmap: no JSON files")
    by_sequence = {}
    for path in files:
        document = json.loads(path.read_text())
        by_sequence.setdefault(document["sequence"], []).append(document)
    if args.label is not None and len(args.label) != len(args.tripose):
        parser.error(f"--label: {len(args.label)} labels for {len(args.tripose)} --tripose files")
    tripose = {}
    for i, item in enumerate(args.tripose):
        sequence, sep, path = item.partition("=")
        if not sep or sequence not in by_sequence:
            parser.error(f"--tripose: {item!r} is not SEQUENCE=TUM with a sequence of the JSON files "
                         f"({', '.join(sorted(by_sequence))})")
        label = args.label[i] if args.label else tripose_label(sequence, Path(path))
        tripose.setdefault(sequence, []).append((label, Path(path)))
    for label, documents in by_sequence.items():
        documents.sort(key=lambda d: d["method"], reverse=True)
        print(plot_sequence(label, documents, tripose.get(label, []), args.output, args.prefix, args.fps))


if __name__ == "__main__":
    main()
