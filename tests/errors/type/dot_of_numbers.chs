# Grübler's formula pasted back as chasles prints it (dof = 3(4 − 1 − 4) + 4·1):
# `·` is the dot product of two vectors; the error says to multiply with *
3(4 − 1 − 4) + 4·1
