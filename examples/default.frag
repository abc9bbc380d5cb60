// default.frag: the scene `raymarching` opens with no argument. It is
// tori.frag, the most striking example that still runs interactively on a CPU
// renderer (docs/examples.md lists every example's frame time).
#include "tori.frag"
