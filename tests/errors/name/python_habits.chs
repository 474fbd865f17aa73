# Lines typed from MATLAB or Python habit: each error's help names the
# chasles way.
syms t1 t2
format long
np.array([1, 2, 3])
import numpy as np
x = math.pi / 2
