# Shared by the phase diagrams (load '../phase_key.gp'): the phases' colours as in the thesis
# (fluid blue, gas orange, coexistence white; solid grey; sfc/sgc pale), their names, and a
# key with one coloured box per phase that a table's label column holds.
color(l) = l eq "s" ? 0x909090 : l eq "f" ? 0x3070d0 : l eq "g" ? 0xf0a030 : \
           l eq "fgc" ? 0xffffff : l eq "sfc" ? 0xd0d0ff : l eq "sgc" ? 0xffe0c0 : 0xff0000
phase_name(l) = l eq "s" ? "solid (s)" : l eq "f" ? "fluid (f)" : l eq "g" ? "gas (g)" : \
           l eq "fgc" ? "fluid-gas coexistence (fgc)" : l eq "sfc" ? "solid-fluid coexistence (sfc)" : \
           l eq "sgc" ? "solid-gas coexistence (sgc)" : l
# phases_in(FILE, COLUMN): the labels found in COLUMN (a string: a number or a header's name) of a
# tab-separated table (or several, FILE = "a.tsv b.tsv"), in the order s sfc f sgc fgc g and
# then any other (drawn red)
phases_in(file, c) = system(sprintf("awk -F'\\t' -v c='%s' 'BEGIN { n = split(\"s sfc f sgc fgc g\", o, \" \") } \
  /^#/ { next } !k && c !~ /^[0-9]+$/ { for (i = 1; i <= NF; i++) if ($i == c) k = i; next } \
  !k { k = c + 0 } $1 == \"file\" || $k == c || $k == \"label\" { next } { seen[$k] = 1 } \
  END { for (i = 1; i <= n; i++) if (o[i] in seen) { printf \"%%s \", o[i]; delete seen[o[i]] } \
        for (p in seen) if (p != \"\") printf \"%%s \", p }' %s", c, file))
# in a plot: for [p in phases] NaN with boxes fs solid 1 border lc rgb "black" lc rgb color(p) title phase_name(p)
