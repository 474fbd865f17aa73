# A space-separated row reads as printed only when every entry is a plain
# number (LANGUAGE.md §4); with anything else it reads two ways.
θ = 30 deg
[0 -1 0; 1 0 0; 0 0 1]
[2 pi]
[cos θ -sin θ; sin θ cos θ]
[R p; 0 1]
