# scripts/farm/sequence.sh: what parallel-render and slurm-render share,
# sourced by both. They set `tool` (their name, for messages) and `here` (the
# repository) first.
#   read_sequence RENDER_ARGS...  sets render_args, frames, pattern, fps, exe
#   slice_ranges SLICES           sets ranges: FIRST:LAST of each slice

# COUNT, OUT_PATTERN and --fps, as render reads them; the binary.
read_sequence() {
  render_args=("$@")
  frames="" pattern="" fps=60
  local dated="" i
  for ((i = 0; i < ${#render_args[@]}; ++i)); do
    case "${render_args[i]}" in
      --frames) frames="${render_args[i + 1]:-}" ;;
      --frames=*) frames="${render_args[i]#--frames=}" ;;
      -o|--output) pattern="${render_args[i + 1]:-}" ;;
      --output=*) pattern="${render_args[i]#--output=}" ;;
      --fps) fps="${render_args[i + 1]:-}" ;;
      --fps=*) fps="${render_args[i]#--fps=}" ;;
      --date|--date=*) dated=1 ;;
      --frame-range*) echo "$tool: the slices are its own --frame-range; give the whole --frames COUNT" >&2; exit 2 ;;
    esac
  done
  [[ "$frames" =~ ^[0-9]+$ && "$frames" -ge 1 ]] || { echo "$tool: give --frames COUNT, the whole sequence" >&2; exit 2; }
  [[ -n "$pattern" ]] || { echo "$tool: give -o OUT_PATTERN, with a counter such as frame_%04d.png" >&2; exit 2; }
  # iDate is the clock when each run starts: every slice gets the same one.
  [[ -n "$dated" ]] || render_args+=(--date "$(date +%Y-%m-%dT%H:%M:%S)")
  exe="${RAYMARCHING:-$(command -v raymarching || echo "$here/build/raymarching")}"
  [[ -x "$exe" ]] || { echo "$tool: no raymarching binary (set RAYMARCHING, or build with scripts/build.sh)" >&2; exit 2; }
}

# Slice k holds frames k*COUNT/N to (k+1)*COUNT/N - 1: sizes differ by one at
# most. No more slices than frames.
slice_ranges() {
  local slices="$1" k
  [[ "$slices" =~ ^[0-9]+$ && "$slices" -ge 1 ]] || { echo "$tool: --slices must be a positive number" >&2; exit 2; }
  (( slices > frames )) && slices=$frames
  ranges=()
  for ((k = 0; k < slices; ++k)); do ranges+=("$(( k * frames / slices )):$(( (k + 1) * frames / slices - 1 ))"); done
}
