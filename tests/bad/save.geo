// save.geo -- box.geo, meshed and saved by the script itself into the
// current directory.  lac's sandbox refuses the write (chapter 01,
// bad-input.md, section 1): lac_sandbox_saved.msh is never made.
Include "box.geo";
Mesh 2;
Save "lac_sandbox_saved.msh";
