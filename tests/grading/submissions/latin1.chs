# A file saved as Latin-1: étudiant
assert 1 == 1  # (a) never read
