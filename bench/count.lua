-- Send a fixed number of select requests per thread, then stop the thread.
-- The load cycles over 1,000 values so that the requests are not all the same query.
-- Usage: wrk ... -s bench/count.lua URL -- <requests per thread>

local next_id = 0

function setup(thread)
  thread:set("offset", next_id * 7919)
  next_id = next_id + 1
end

function init(args)
  limit = tonumber(args[1])
  sent = 0
  received = 0
end

function request()
  sent = sent + 1
  local load = 50 + ((offset + sent) % 1000)
  return wrk.format(nil, string.format(
    "/api/v1/select?load_n=%d&speed_mm_s=50&length_mm=500&lead_mm=10", load))
end

function response(status, headers, body)
  received = received + 1
  if received >= limit then
    wrk.thread:stop()
  end
end
