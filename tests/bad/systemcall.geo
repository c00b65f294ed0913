// systemcall.geo -- box.geo, then a command: gmsh would run it with
// /bin/sh.  lac's sandbox ends the child instead (chapter 01,
// bad-input.md, section 1): nothing is run, lac_sandbox_touched is never
// made.
Include "box.geo";
SystemCall "touch lac_sandbox_touched";
