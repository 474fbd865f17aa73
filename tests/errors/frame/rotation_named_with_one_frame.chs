# LANGUAGE.md §2: the part after `_` is a frame subscript, so R_x names a
# rotation tagged {x}, and R_z R_y R_x asks {z}, {y}, {x} to cancel. The
# help says so and names Rz, Ry, Rx (no underscore).
R_x = Rotx(30 deg)
R_y = Roty(45 deg)
R_z = Rotz(60 deg)
R_z R_y R_x                   # error
Rx = Rotx(30 deg)
Ry = Roty(45 deg)
Rz = Rotz(60 deg)
Rz Ry Rx
