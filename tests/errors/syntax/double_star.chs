# power written as **
x = 2 ** 3
