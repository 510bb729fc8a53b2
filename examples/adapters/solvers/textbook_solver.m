% [s, which] = textbook_solver(u, dy, phi): stable_solver.m with one fault
% planted: the release root as printed, (A.25), which cancels where
% u >> sqrt(phi) dy. An example of a wrong solver for the adapter.
function [s, which] = textbook_solver(u, dy, phi)
  if ~isfinite(u) || ~isfinite(dy) || ~isfinite(phi) || phi < 0
    s = NaN; which = 0; return;
  end
  if dy <= 0
    if u <= -dy
      s = -u; which = 1;
      return;
    end
    % impact, (A.11): every term has the sign of s (u > 0, dy <= 0)
    s = (2 * phi * dy - u - sqrt(u^2 - 4 * phi * dy * (u + dy))) / (2 * (1 + phi));
    which = 2;
    return;
  end
  if u >= dy * (phi - 1)
    % contact, (A.19): 2 phi dy - u cancels where u is near 2 phi dy, so
    % 2 phi dy is carried as an exact sum of two doubles (Dekker's product)
    [high, low] = exact_product(2 * phi, dy);
    s = ((high - u) + low) / (1 + phi); which = 3;
  else
    % release, (A.25) as printed: -u and the square root cancel where
    % u >> sqrt(phi) dy, the fault this example plants
    s = -u / 2 + sqrt(u^2 + 4 * phi * dy^2) / 2;
    which = 4;
  end
end

% a * b = high + low exactly (Veltkamp's split; no fma in Octave)
function [high, low] = exact_product(a, b)
  high = a * b;
  [a1, a2] = split(a);
  [b1, b2] = split(b);
  low = ((a1 * b1 - high) + a1 * b2 + a2 * b1) + a2 * b2;
end

function [upper, lower] = split(x)
  c = 134217729 * x;  % 2^27 + 1
  upper = c - (c - x);
  lower = x - upper;
end
