# Reads libpfmath/functions.def (the function set, declared once) for make:
#   awk -v want=LIST -f mk/funcset.awk libpfmath/functions.def
# LIST is one of
#   lib_gen      name:exact name:fast per PF_FLOAT row (LIB_GEN)
#   float_sweep  name:exact:ULP name:fast: per PF_FLOAT row (make sweep)
#   fx_lib       name/func/T/T2 per PF_FIXED row (FX_LIB)
#   fx_sweep     name/func/T/T2/LSB per PF_FIXED row (make sweep-fixed)
# T = fixed<size,exp> or ufixed<size,exp>, spelled as the generated files'
# provenance records them.  Rows are one per line (see functions.def).
function args(line,    s) {
    s = line
    sub(/^[A-Z_]+\(/, "", s)
    sub(/\)[ \t]*$/, "", s)
    gsub(/[ \t]/, "", s)
    return split(s, a, ",")
}
function type(sg, size, e) { return (sg == 1 ? "fixed<" : "ufixed<") size "," e ">" }
/^PF_FLOAT\(/ {
    if (args($0) != 6) { print "functions.def: bad PF_FLOAT row: " $0 > "/dev/stderr"; exit 1 }
    if (want == "lib_gen") out = out " " a[1] ":exact " a[1] ":fast"
    if (want == "float_sweep") out = out " " a[1] ":exact:" a[4] " " a[1] ":fast:"
}
/^PF_FIXED\(/ {
    if (args($0) != 14) { print "functions.def: bad PF_FIXED row: " $0 > "/dev/stderr"; exit 1 }
    t = a[1] "/" a[2] "/" type(a[5], a[6], a[7]) "/" type(a[9], a[10], a[11])
    if (want == "fx_lib") out = out " " t
    if (want == "fx_sweep") out = out " " t "/" a[12]
}
END { sub(/^ /, "", out); print out }
