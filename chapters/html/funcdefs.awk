# funcdefs.awk -- "name <TAB> file <TAB> line" for every function defined
# in the C files given (GNU style: the name at column 0 followed by " (");
# links.lua links `name` in the text of a page to its definition.
/^[A-Za-z_][A-Za-z0-9_]* \(/ && FILENAME ~ /\.c$/ { printf "%s\t%s\t%d\n", $1, FILENAME, FNR }
