-- Every request a different query (the load changes by 1 mN each time), so that no
-- response can come from the app's cache: the cost of computing each selection.
-- Usage: wrk ... -s bench/distinct.lua URL -- "<path with %s where the load goes>"

local next_id = 0

function setup(thread)
  thread:set("offset", next_id * 1000000)
  next_id = next_id + 1
end

function init(args)
  template = args[1]
  sent = 0
end

function request()
  sent = sent + 1
  local load = string.format("%.3f", 50 + (offset + sent) / 1000)
  return wrk.format(nil, string.format(template, load))
end
