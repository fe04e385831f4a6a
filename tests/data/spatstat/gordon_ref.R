# Reference values for a window with holes: spatstat's gordon (people in Gordon Square, London;
# outer ring and two holes). Run: Rscript gordon_ref.R OUTDIR
suppressMessages(library(spatstat))
out <- commandArgs(trailingOnly = TRUE)[1]
X <- gordon
W <- Window(X)
options(digits = 15)
write.csv(data.frame(x = X$x, y = X$y), file.path(out, "gordon_points.csv"), row.names = FALSE)
ring <- function(b) paste(sprintf("%.15g %.15g", c(b$x, b$x[1]), c(b$y, b$y[1])), collapse = ", ")
wkt <- paste0("POLYGON(", paste(sapply(W$bdry, function(b) paste0("(", ring(b), ")")), collapse = ", "), ")")
writeLines(c(paste("wkt", wkt)), file.path(out, "gordon_window.txt"))
# Exact set covariance |W ∩ (W + v)| (overlap.owin) at shifts on a grid.
vs <- expand.grid(vx = c(-12, -5, -1.5, 0, 0.7, 3, 8, 20), vy = c(-9, -2.5, 0, 1.2, 6, 15))
vs$overlap <- mapply(function(vx, vy) overlap.owin(W, shift(W, c(vx, vy))), vs$vx, vs$vy)
write.csv(vs, file.path(out, "gordon_setcov.csv"), row.names = FALSE)
# Ripley's isotropic weights (exact for polygons): every point at a few radii.
rs <- c(1, 3, 6, 10)
rip <- do.call(rbind, lapply(rs, function(r) data.frame(point = seq_len(npoints(X)) - 1, r = r,
                                                         weight = as.numeric(edge.Ripley(X, matrix(r, npoints(X), 1))))))
write.csv(rip, file.path(out, "gordon_ripley.csv"), row.names = FALSE)
r <- seq(0, 10, length.out = 51)
g <- pcf(X, r = r, correction = c("translate", "Ripley"), divisor = "r")
write.csv(data.frame(r = g$r, trans = g$trans, iso = g$iso), file.path(out, "gordon_pcf.csv"), row.names = FALSE)
guard <- erosion(W, 0.05 * sqrt(area(W)))
ce <- c(naive = clarkevans(X, correction = "none"), cdf = clarkevans(X, correction = "cdf"),
        guard = clarkevans(X, correction = "guard", clipregion = guard))
write.csv(data.frame(name = "gordon", n = npoints(X), area_m2 = area(W), perimeter_m = perimeter(W),
                     mean_nn = mean(nndist(X)), ce_naive = ce[["naive"]], ce_cdf = ce[["cdf"]], ce_guard = ce[["guard"]],
                     n_in_guard = sum(inside.owin(X$x, X$y, guard))),
          file.path(out, "gordon_summary.csv"), row.names = FALSE)
