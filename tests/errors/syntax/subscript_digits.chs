# the book's θ₁ copied as typeset: the help spells it θ1
θ₁ = 30°
