# funcs.awk -- for each line of the C files given that holds a [LAC ...]
# tag: "file <TAB> line <TAB> function", the function whose body holds the
# line, or else the next one defined in the file (its comment); empty in
# the file's head (before its first #include), in a header and after the
# last function.  GNU style: the name at column 0
# followed by " (", the body between "{" and "}" at column 0.
function flush(name,   k) {
  for (k = 1; k <= np; k++) printf "%s\t%s\t%s\n", FILENAME, pend[k], name
  np = 0
}
FNR == 1 { if (NR > 1) flush(""); body = 0; fn = ""; head = 1 }
/^#include/ { head = 0 }
/^[A-Za-z_][A-Za-z0-9_]* \(/ && FILENAME ~ /\.c$/ {
  fn = $1; flush(fn)
}
/^\{/ { body = 1 }
/\[LAC [^]]*\]/ {
  if (body || head) printf "%s\t%s\t%s\n", FILENAME, FNR, head ? "" : fn
  else pend[++np] = FNR
}
/^\}/ { body = 0 }
END { flush("") }
