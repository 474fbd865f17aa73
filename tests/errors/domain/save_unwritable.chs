# save writes .svg or .png files; an unwritable path is an error and no
# file is left behind.
save(draw(Rotz(1)), "/no-such-folder/pic.svg")
save(draw(Rotz(1)), "pic.pdf")
