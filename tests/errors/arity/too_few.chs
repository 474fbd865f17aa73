# too few arguments
RpToTrans(Rotz(1))
