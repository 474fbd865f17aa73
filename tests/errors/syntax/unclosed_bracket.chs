# an unclosed bracket
R = [1, 0, 0; 0, 1, 0; 0, 0, 1
x = 2
