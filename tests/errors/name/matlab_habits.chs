# MATLAB and Python habits get the chasles way, and a conversion name points
# to the function that does that conversion (RotToQuat → quat, not RotQuat).
R = Rotz(30 deg)
sind(30)
RotToQuat(R)
quat2rotm((1, 0, 0, 0))
rotm2eul(R)
disp(R)
quit
help
True
