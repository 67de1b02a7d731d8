# Flags Fortran constructs that give a procedure state shared between calls (and so between
# threads): SAVE, COMMON, DATA, module variables that are neither PARAMETER nor PROTECTED, and
# local variables initialised in their declaration (implicit SAVE). Simple line-based scan:
# strings and comments are stripped and continuation lines joined first; main programs are
# skipped; declarations inside derived-type definitions (default component values) and
# interface blocks are not checked. Prints "file:line: reason: text" per problem.
function report(reason) {
   printf "%s:%d: %s: %s\n", FILENAME, start_line, reason, original
   problems++
}
FNR == 1 { in_module_spec = 0; in_type = 0; in_interface = 0; in_program = 0; pending = "" }
{
   raw = $0
   line = tolower($0)
   gsub(/'[^']*'/, "''", line)
   gsub(/"[^"]*"/, "\"\"", line)
   sub(/!.*/, "", line)
   if (pending != "") {
      sub(/^[ \t]*&/, "", line)
      line = pending " " line
      original = original " " raw
   } else {
      start_line = FNR
      original = raw
   }
   if (line ~ /&[ \t]*$/) {
      sub(/&[ \t]*$/, "", line)
      pending = line
      next
   }
   pending = ""
   gsub(/^[ \t]+/, "", original)

   if (line ~ /^[ \t]*program[ \t]/) { in_program = 1; next }
   if (line ~ /^[ \t]*end[ \t]*program/) { in_program = 0; next }
   if (in_program) next

   if (line ~ /(^|[^a-z0-9_])save([^a-z0-9_]|$)/) report("SAVE")
   if (line ~ /(^|[^a-z0-9_])common[ \t]*\//) report("COMMON block")
   if (line ~ /^[ \t]*data[ \t]/) report("DATA statement (implicit SAVE)")

   if (line ~ /^[ \t]*module[ \t]+[a-z0-9_]+[ \t]*$/ && line !~ /^[ \t]*module[ \t]+procedure/) {
      in_module_spec = 1
      next
   }
   if (line ~ /^[ \t]*contains[ \t]*$/ || line ~ /^[ \t]*end[ \t]*module/) { in_module_spec = 0; next }
   if (line ~ /^[ \t]*(abstract[ \t]+)?interface([ \t]|$)/) { in_interface = 1; next }
   if (line ~ /^[ \t]*end[ \t]*interface/) { in_interface = 0; next }
   if (line ~ /^[ \t]*type[ \t]*(,|::|[ \t]+[a-z])/ ) { in_type = 1; next }
   if (line ~ /^[ \t]*end[ \t]*type/) { in_type = 0; next }
   if (in_type || in_interface) next

   if (line ~ /^[ \t]*(integer|real|logical|character|complex|double[ \t]*precision|type[ \t]*\(|class[ \t]*\()/ \
       && index(line, "::") > 0) {
      attrs = substr(line, 1, index(line, "::") - 1)
      rest = substr(line, index(line, "::") + 2)
      if (attrs ~ /parameter/) next
      if (in_module_spec) {
         if (attrs !~ /protected/) report("module variable neither PARAMETER nor PROTECTED")
      } else if (rest ~ /=/) {
         report("variable initialised in its declaration (implicit SAVE)")
      }
   }
}
END {
   printf "checked %d file(s): found %d problem(s)\n", files_checked, problems + 0
   exit (problems > 0)
}
