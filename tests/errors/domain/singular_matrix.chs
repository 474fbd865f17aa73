# inverting a singular matrix
inv([1, 2; 2, 4])
