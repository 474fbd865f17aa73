# long frame names keep their braces in the suggested fix
T_{world,cam} = Trans((1, 0, 0))
T_{base,cam} = Trans((0, 1, 0))
T_{world,cam} * T_{base,cam}
T_{base,world} = T_{world,cam} * inv(T_{base,cam})
