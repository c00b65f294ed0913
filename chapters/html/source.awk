# source.awk -- one source file as an HTML page, line n anchored #L<n>
# (make-html.sh; -v name=PATH -v root=PREFIX to the top of the pages).
function esc(s) {
  gsub(/&/, "\\&amp;", s); gsub(/</, "\\&lt;", s); gsub(/>/, "\\&gt;", s)
  return s
}
BEGIN {
  printf "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
  printf "<title>lac: %s</title>\n", esc(name)
  printf "<style>body { margin: 1em; font-family: \"DejaVu Sans\", sans-serif; }\n"
  printf "pre { font-family: \"DejaVu Sans Mono\", monospace; font-size: 0.85em; }\n"
  printf "a.n { color: #999; text-decoration: none; display: inline-block; width: 4em; }\n"
  printf ":target { background: #ffe79a; }</style>\n</head>\n<body>\n"
  printf "<nav><a href=\"%sREADME.html\">lac</a> &middot; <a href=\"%sequations.html\">Equations to code</a></nav>\n", root, root
  printf "<h1>%s</h1>\n<pre>", esc(name)
}
{ printf "<span id=\"L%d\"><a class=\"n\" href=\"#L%d\">%d</a>%s</span>\n", NR, NR, NR, esc($0) }
END { printf "</pre>\n</body>\n</html>\n" }
