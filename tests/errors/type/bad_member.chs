# a member that does not exist
Rotz(1).p
