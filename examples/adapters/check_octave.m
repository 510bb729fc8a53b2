% contact-solve's line protocol for a MATLAB/Octave solver of (A.2):
%
%   octave-cli examples/adapters/check_octave.m PATH/TO/mysolver.m
%
% mysolver.m defines [s, which] = mysolver(u, dy, phi) (which: 1 free,
% 2 impact, 3 contact, 4 release, 0 invalid input with s = NaN). Standard
% input holds lines "u dy phi" (C99 hex floats, as contact-check writes them,
% or decimals); each answer is a line "s which" with 17 significant digits,
% which read back as the same double. A line that is not three numbers stops
% the adapter with the line's number.
1;

function x = hex_or_decimal(text)
  % C99 hex floats, [-]0xH.HHHp[+-]D, exactly: the significand's hex digits
  % are an integer below 2^53 and pow2 scales it without rounding.
  t = regexp(text, '^(?<sign>[+-]?)0[xX](?<whole>[0-9a-fA-F]*)\.?(?<fraction>[0-9a-fA-F]*)[pP](?<exponent>[+-]?\d+)$', ...
             'names', 'once');
  if isempty(t) || isempty(fieldnames(t))
    x = str2double(text);  % decimals, inf, nan
    if isnan(x) && isempty(regexpi(text, '^[+-]?nan$', 'once'))
      x = [];
    end
    return;
  end
  digits = [t.whole t.fraction];
  significand = 0;
  for d = digits
    significand = significand * 16 + hex2dec(d);
  end
  x = pow2(significand, str2double(t.exponent) - 4 * numel(t.fraction));
  if strcmp(t.sign, '-')
    x = -x;
  end
end

arguments = argv();
if numel(arguments) ~= 1
  fprintf(stderr, 'usage: octave-cli check_octave.m PATH/TO/solver.m\n');
  exit(2);
end
[folder, name] = fileparts(arguments{1});
if ~isempty(folder)
  addpath(folder);
end
solver = str2func(name);

text = fread(stdin, Inf, 'char=>char')';
lines = strsplit(text, "\n");
answers = repmat({''}, 1, numel(lines));
for k = 1:numel(lines)
  fields = strsplit(strtrim(lines{k}));
  if isempty(fields{1})
    continue;
  end
  values = cellfun(@hex_or_decimal, fields, 'UniformOutput', false);
  if numel(fields) ~= 3 || any(cellfun(@isempty, values))
    fflush(stdout);
    fprintf(stderr, 'stdin:%d: expected "u dy phi", got "%s"\n', k, lines{k});
    exit(2);
  end
  [s, which] = solver(values{1}, values{2}, values{3});
  answers{k} = sprintf('%.17g %d\n', s, which);
end
fputs(stdout, [answers{:}]);
