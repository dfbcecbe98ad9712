"""Test helper for tables of cases that mix scene keywords and a call's options in one dict."""

import covopt

SCENE_KEYWORDS = {name for name in dir(covopt.Scene) if isinstance(getattr(covopt.Scene, name),
                                                                   property)}


def call(function, *args, **keywords):
    """function(*args, Scene(scene keywords), options): the scene first, or scene= for sweep and
    check_trajectory; optimize's covering_poisson is its option. Returns the result's to_dict()."""
    own = {"covering_poisson"} if function is covopt.optimize else set()
    scene = covopt.Scene(**{k: v for k, v in keywords.items() if k in SCENE_KEYWORDS - own})
    options = {k: v for k, v in keywords.items() if k not in SCENE_KEYWORDS - own}
    if function in (covopt.sweep, covopt.check_trajectory):
        return function(*args, scene=scene, **options).to_dict()
    return function(scene, *args, **options).to_dict()
