# MATLAB reads [1 -x] as two entries and chasles as 1 - x: a sign with space
# before it and none after is refused with both readings. Plain numbers read
# as MATLAB prints them: [1 -2] is two entries.
[1 -2]
[1 -x]
[1, 2; 3 +4, 5]
[1 - 2]
[1, -2]
