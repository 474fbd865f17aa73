# `sin θ` applies to the one atom after it (LANGUAGE.md §4); where the
# book's reader could take more, the error shows both readings.
θ = 30 deg
sin θ
sin θ^2
sin 2θ
cos θ/2
cos θ / 2
