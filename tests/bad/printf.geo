// printf.geo -- box.geo, then a line appended to a file by Printf.
// lac's sandbox refuses the write (chapter 01, bad-input.md, section 1).
Include "box.geo";
Printf("level = %g", level) >> "lac_sandbox_printf.txt";
