// createdir.geo -- box.geo, then a directory made by the script.  lac's
// sandbox refuses it (chapter 01, bad-input.md, section 1).
Include "box.geo";
CreateDir "lac_sandbox_dir";
