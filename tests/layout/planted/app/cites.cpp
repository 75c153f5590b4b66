// Planted citations of the design notes: the first is right, the others
// are findings (no such section, no such file, no folder).
// (lib/DESIGN.md "Real
// section")
// (lib/DESIGN.md "Why the error floor")
int cited = 0;  // (DESIGN: the old way)
// (geometry/DESIGN.md)
