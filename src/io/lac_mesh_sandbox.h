/* lac_mesh_sandbox.h -- what gmsh may do in lac's child process  [LAC §2]
 *
 * A .geo file is a program for gmsh, and scenes and .geo files are passed
 * around in class.  gmsh's language can start programs (SystemCall,
 * NonBlockingSystemCall, OnelabRun) and write, remove or rename files
 * (Save, Print, Printf > "FILE", CreateDir; newer versions DeleteFile,
 * RenameFile), and
 * gmshInitialize itself writes FLTK's preferences into ~/.fltk (and, run
 * by root, /etc/fltk).  Opening a mesh with lac must do none of this, so
 * the child process that runs gmsh (lac_mesh_child.h) closes those doors
 * with seccomp filters (Linux), in two steps:
 *
 *   LAC_SANDBOX_INIT    before gmshInitialize: starting a program ends
 *                       the child; a call that would create, write,
 *                       remove, rename or change a file fails with EACCES,
 *                       which FLTK takes silently;
 *   LAC_SANDBOX_SCRIPT  after it, before the file is opened: such a call
 *                       ends the child too, so that a script that tries is
 *                       an error, not a result made without its side
 *                       effect.
 *
 * Reading stays allowed (Include, Merge: any file the user can read),
 * and so do threads, memory and writing to the pipes the child already
 * holds; network sockets, ptrace and mounting fail with EACCES.  A call
 * that ends the child makes it write one line "lac-sandbox: WHAT" to its
 * stderr (the parent's pipe) and exit with LAC_SANDBOX_EXIT;
 * lac_mesh_sandbox_verdict turns that into the message "gmsh could not mesh
 * 'x.geo': the script tried to write 'x.msh' (openat): writes outside
 * lac's output are not allowed ...".
 *
 * The filters cannot be removed: lac_mesh_sandbox_enter is for the child
 * process only.  Where seccomp is missing (a kernel without it, an
 * architecture other than x86-64 and aarch64) it fails, and lac does not
 * run gmsh.
 */
#ifndef LAC_MESH_SANDBOX_H
#define LAC_MESH_SANDBOX_H

enum { LAC_SANDBOX_INIT, LAC_SANDBOX_SCRIPT };

/* The exit status of a child that tried what the sandbox forbids. */
#define LAC_SANDBOX_EXIT 121

/* In the child: close the doors of the given step (see above).
 * LAC_SUCCESS, or LAC_EDEP with a message if the filter cannot be set. */
int lac_mesh_sandbox_enter (int step);

/* In the parent: if the child (wait status ws, the end of its stderr in
 * talk) was stopped by the sandbox, store the message for `verb` ("read"
 * or "mesh") and `path` and return LAC_EIO; else return LAC_SUCCESS. */
int lac_mesh_sandbox_verdict (int ws, const char *talk, const char *verb,
                              const char *path);

#endif /* LAC_MESH_SANDBOX_H */
