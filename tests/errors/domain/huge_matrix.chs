# absurd sizes are refused, not allocated
zeros(100000000, 100000000)
