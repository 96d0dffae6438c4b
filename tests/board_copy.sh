# Sourced by the shell tests: board_copy ROOT BOARD DIR makes DIR/board.toml, a scratch copy
# of boards/BOARD with its calibration and its own copy of machines/, to edit freely.
board_copy() {
  mkdir -p "$3" && cp "$1/boards/$2/board.toml" "$1/boards/$2/calibration.toml" "$3/" &&
    cp -r "$1/machines" "$3/"
}
