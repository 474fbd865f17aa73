# `I` takes its size from what it is added to or multiplied with
# (LANGUAGE.md §4); alone it has none.
W = [(0, 0, 1)]
I + W
T = Trans((1, 2, 3))
T - I
I
