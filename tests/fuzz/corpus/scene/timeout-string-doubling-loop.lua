local s = string.rep('x', 1 << 20)
while true do s0= s .. s end
