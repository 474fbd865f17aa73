# MATLAB reads [1 -2] as two entries; chasles separates entries with commas,
# so a sign with space before it and none after is refused with both fixes
[1 -2]
[1, 2; 3 +4, 5]
[1 - 2]
[1, -2]
