"""The public functions document their arguments and the package its conventions."""
import pydoc

import tripose


def test_every_public_function_has_a_docstring():
    for name in tripose.__all__:
        function = getattr(tripose, name)
        assert function.__doc__ and len(function.__doc__.strip()) > 80, name


def test_ransac_help_mentions_threshold_and_conventions():
    text = pydoc.render_doc(tripose.estimate_pose_line_point_ransac, renderer=pydoc.plaintext)
    assert "threshold" in text and "pixels" in text
    # The conventions: what the pose maps, where the views are, and what the observations are.
    module_text = pydoc.render_doc(tripose, renderer=pydoc.plaintext)
    for phrase in ("x_cam = R @ X + t", "view 1 is at [I|0]", "R12|t12", "pixels", "NaN", "GIL"):
        assert phrase in module_text, phrase


def test_help_of_the_ransac_function_names_the_conventions_itself():
    # help(tripose.estimate_pose_line_point_ransac) alone (what users type) must say how the pose
    # is defined: the function's own text, not only the module's.
    text = pydoc.render_doc(tripose.estimate_pose_line_point_ransac, renderer=pydoc.plaintext)
    assert "view 3" in text
    assert "x_cam" in text or "conventions" in text.lower(), \
        "help(tripose.estimate_pose_line_point_ransac) neither states the pose convention nor points to it"
