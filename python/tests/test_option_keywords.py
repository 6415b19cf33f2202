"""Every option class takes any of its fields as a keyword: the defaults are the core's, declared
once; a keyword that is no field, or a value its field does not take, is an error naming it."""
import pytest

import tripose

OPTION_CLASSES = [tripose.RansacOptions, tripose.RefineOptions, tripose.MatchOptions, tripose.TrackerOptions]


def fields(cls):
    """The fields of an option class: its writable properties."""
    return [name for name, member in vars(cls).items() if isinstance(member, property) and member.fset is not None]


def values(options):
    """Every field's value, the nested option classes' as dicts of theirs."""
    out = {}
    for name in fields(type(options)):
        value = getattr(options, name)
        out[name] = values(value) if type(value) in OPTION_CLASSES else value
    return out


def test_every_class_has_fields():
    counts = {cls.__name__: len(fields(cls)) for cls in OPTION_CLASSES}
    assert counts == {"RansacOptions": 8, "RefineOptions": 4, "MatchOptions": 7, "TrackerOptions": 12}


@pytest.mark.parametrize("cls", OPTION_CLASSES, ids=lambda cls: cls.__name__)
def test_keywords_equal_to_the_defaults_give_the_defaults(cls):
    defaults = cls()
    every = cls(**{name: getattr(defaults, name) for name in fields(cls)})
    assert values(every) == values(defaults) == values(cls())


def test_keywords_set_their_fields_and_leave_the_others():
    options = tripose.RansacOptions(threshold=3, min_inliers=5)
    assert options.threshold == 3.0 and options.min_inliers == 5
    expected = values(tripose.RansacOptions())
    expected.update(threshold=3.0, min_inliers=5)
    assert values(options) == expected

    refine = tripose.RefineOptions(max_iterations=50, loss="cauchy", loss_scale=0.5)
    assert (refine.max_iterations, refine.loss, refine.loss_scale) == (50, "cauchy", 0.5)
    assert refine.tolerance == tripose.RefineOptions().tolerance

    matching = tripose.MatchOptions(point_ratio=0.7, min_fundamental_inliers=12)
    assert (matching.point_ratio, matching.min_fundamental_inliers) == (0.7, 12)


def test_nested_options_are_keywords_too():
    tracker = tripose.TrackerOptions(window=4, ransac=tripose.RansacOptions(threshold=1.5),
                                     matching=tripose.MatchOptions(epipolar_distance=3.0))
    assert tracker.window == 4 and tracker.ransac.threshold == 1.5 and tracker.matching.epipolar_distance == 3.0
    ransac = tripose.RansacOptions(refine_options=tripose.RefineOptions(loss="huber"))
    assert ransac.refine_options.loss == "huber"


def test_options_built_from_keywords_are_what_the_functions_take():
    tracker = tripose.Tracker(K=[[500, 0, 320], [0, 500, 240], [0, 0, 1]],
                              options=tripose.TrackerOptions(window=3, min_inliers=12))
    assert tracker.options.window == 3 and tracker.options.min_inliers == 12


@pytest.mark.parametrize("cls", OPTION_CLASSES, ids=lambda cls: cls.__name__)
def test_an_unknown_keyword_is_a_type_error_naming_it(cls):
    with pytest.raises(TypeError, match=rf"{cls.__name__}\(\) got an unexpected keyword argument 'no_such_field'"):
        cls(no_such_field=1)


def test_the_unknown_keyword_error_lists_the_fields():
    with pytest.raises(TypeError, match="'thresold'; its fields are threshold, confidence"):
        tripose.RansacOptions(thresold=3)


def test_positional_arguments_are_refused():
    with pytest.raises(TypeError):
        tripose.RansacOptions(3.0)


def test_a_wrong_value_raises_as_setting_the_field_does():
    cases = [(tripose.RansacOptions, "threshold", "three"), (tripose.RansacOptions, "max_iterations", 2.5),
             (tripose.RansacOptions, "seed", -1), (tripose.RansacOptions, "refine_options", 3),
             (tripose.RefineOptions, "loss", "l1"), (tripose.TrackerOptions, "ransac", tripose.RefineOptions())]
    for cls, name, value in cases:
        with pytest.raises(Exception) as by_setting:
            setattr(cls(), name, value)
        with pytest.raises(type(by_setting.value), match=name) as by_keyword:
            cls(**{name: value})
        # The setter's own error is kept as the cause.
        assert type(by_keyword.value.__cause__) is type(by_setting.value), (cls.__name__, name)
        assert str(by_keyword.value.__cause__) == str(by_setting.value), (cls.__name__, name)


def test_a_wrong_type_names_the_keyword_value_and_type():
    with pytest.raises(TypeError, match=r"RansacOptions\(\): threshold='three' is not a valid float"):
        tripose.RansacOptions(threshold="three")
    with pytest.raises(ValueError, match=r"RefineOptions\(\) argument loss: loss must be 'squared', 'huber' or "
                                         r"'cauchy', got 'l1'"):
        tripose.RefineOptions(loss="l1")


def test_the_signature_lists_the_fields_with_their_defaults():
    signature = tripose.RansacOptions.__init__.__doc__.splitlines()[0]
    defaults = tripose.RansacOptions()
    for name in fields(tripose.RansacOptions):
        assert f"{name}: " in signature, name
    assert f"threshold: float = {defaults.threshold!r}" in signature
    assert f"min_inliers: int = {defaults.min_inliers!r}" in signature
    assert "refine_options: RefineOptions = ..." in signature
