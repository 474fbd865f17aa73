# `explain` shows a book algorithm's steps (LANGUAGE.md §14): an expression
# with none at its top, or a bare name, is refused with what it covers.
x = 3
explain 1 + 2
explain x
