# empty brackets are an error, not a crash (fuzz finding)
x = 1
[]
log([ ])
x
