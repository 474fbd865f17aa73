# explain shows how an expression is computed; a binding is a statement
# of its own, so `explain w = log(R)` asks for the two at once.
R = Rotz(1);
explain w = log(R)
