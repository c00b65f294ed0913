-- links.lua -- pandoc filter of make doc (chapters/html/make-html.sh)
--
-- Metadata in: docdir (the page's folder, relative to the repository),
-- filelist (the repository's files, one a line), needlist (where the files
-- to show as source pages are appended).  A relative link to a page X.md
-- becomes X.html, to a folder its README.html, to any other file of the
-- repository the page that shows it (X.html, lines anchored #L<n>).  Code
-- spans naming a file of the repository (src/fem/lac_spaces.c,
-- lac_spaces.c, lac_spaces.c:120, a module lac_spaces) become links too,
-- and {\rm x} in maths \mathrm{x}.
-- A link that leaves the repository or names nothing in it stops pandoc.

local docdir, files, basenames, need = ".", {}, {}, nil
local funcs = {}          -- function name -> "file#Lline" of its definition

local function norm(path)
  local out = {}
  for part in path:gmatch("[^/]+") do
    if part == ".." then
      if #out == 0 or out[#out] == ".." then
        out[#out + 1] = ".."
      else
        out[#out] = nil
      end
    elseif part ~= "." then
      out[#out + 1] = part
    end
  end
  return table.concat(out, "/")
end

-- from the page's folder to a path relative to the repository
local function rel(target)
  local up = {}
  for _ in docdir:gmatch("[^/]+") do up[#up + 1] = ".." end
  if docdir == "." then up = {} end
  local r = table.concat(up, "/")
  if r == "" then return target end
  return r .. "/" .. target
end

local function isdir(path)
  local prefix = path .. "/"
  for f in pairs(files) do
    if f:sub(1, #prefix) == prefix then return true end
  end
  return false
end

-- the page a repository path is shown at (nil: not in the repository)
local function page_of(path)
  if files[path] then
    if path:match("%.md$") then return (path:gsub("%.md$", ".html")) end
    if path:match("%.png$") or path:match("%.svg$") then
      need:write("=", path, "\n")                -- copied, not shown
      return path
    end
    need:write(path, "\n")
    return path .. ".html"
  end
  if path == "" then path = "." end
  if (path == "." and files["README.md"]) or files[path .. "/README.md"] then
    return (path == "." and "" or path .. "/") .. "README.html"
  end
  return nil
end

local function meta(m)
  if m.docdir then docdir = pandoc.utils.stringify(m.docdir) end
  local fl = pandoc.utils.stringify(m.filelist)
  for line in io.lines(fl) do
    files[line] = true
    local b = line:match("([^/]+)$")
    basenames[b] = basenames[b] == nil and line or false   -- false: ambiguous
  end
  need = assert(io.open(pandoc.utils.stringify(m.needlist), "a"))
  if m.funclist then
    for line in io.lines(pandoc.utils.stringify(m.funclist)) do
      local name, file, ln = line:match("^([^\t]+)\t([^\t]+)\t(%d+)$")
      if name and funcs[name] == nil then funcs[name] = { file, ln } end
    end
  end
end

local function is_external(t)
  return t:match("^%a[%w+.-]*:") or t:match("^#") or t == ""
end

local function link(el)
  if is_external(el.target) then return nil end
  local path, frag = el.target:match("^([^#]*)(#?.*)$")
  local full = norm((docdir == "." and "" or docdir .. "/") .. path)
  if full:match("^%.%.") then
    error("link out of the repository in " .. docdir .. ": " .. el.target)
  end
  local p = page_of(full)
  if not p then
    error("link to a missing file in " .. docdir .. ": " .. el.target)
  end
  el.target = rel(p) .. frag
  return el
end

local function image(el)
  if is_external(el.src) then return nil end
  local full = norm((docdir == "." and "" or docdir .. "/") .. el.src)
  if full:match("^%.%.") or not files[full] then
    error("image out of the repository or missing in " .. docdir .. ": " .. el.src)
  end
  need:write("=", full, "\n")                -- copied, not shown
  return nil
end

-- {\rm x} (plain TeX) as {\mathrm{x}}: texmath, pandoc's TeX reader, knows
-- only the latter
local function math(el)
  el.text = el.text:gsub("{\\rm%s+([^{}]*)}", "{\\mathrm{%1}}")
  return el
end

-- a code span that names a file of the repository, with an optional line
local function code(el)
  local text = el.text:gsub("%.%[ch%]$", ".c")    -- lac_x.[ch]: the .c
  local name, line = text:match("^([%w_./-]+%.%a+):(%d+)$")
  if not name then name = text:match("^([%w_./-]+%.%a+)$") end
  local path
  if name then
    local here = norm((docdir == "." and "" or docdir .. "/") .. name)
    if files[here] then path = here
    elseif files[name] then path = name
    elseif files["src/" .. name] then path = "src/" .. name
    elseif not name:find("/") and basenames[name] then path = basenames[name]
    end
  elseif el.text:match("^lac_[%w_]+ ?%(?%)?$") then
    local fname = el.text:match("^(lac_[%w_]+)")
    local f = funcs[fname]
    if f then
      local p = page_of(f[1])
      if p then
        return pandoc.Link({el}, rel(p) .. "#L" .. f[2]), false
      end
    end
    local b = basenames[fname .. ".h"]
    if b and fname == el.text then path = b end
  end
  if not path then return nil end
  local p = page_of(path)
  if not p then return nil end
  -- a line of a chapter's program: its plain listing (the commented
  -- program has no line numbers)
  if line and path:match("^chapters/[^/]+/example%.c$") then p = path .. ".src.html" end
  -- false: not into the new link (its code span would be linked again)
  return pandoc.Link({el}, rel(p) .. (line and ("#L" .. line) or "")), false
end

-- an image alone in its paragraph (pandoc's implicit figure): a figure
-- whose image links to the file itself (full size), with the caption
-- (the image's text) under it and as its alt text
local function figure(el)
  if #el.content ~= 1 or el.content[1].t ~= "Image" then return nil end
  local img = el.content[1]
  if #img.caption == 0 then
    error("an image without a caption (alt text) in " .. docdir .. ": " .. img.src)
  end
  local alt = pandoc.utils.stringify(img.caption)
  local shown = pandoc.Image({pandoc.Str(alt)}, img.src, "", img.attr)
  return pandoc.Div({
    pandoc.Para({pandoc.Link({shown}, img.src, "full size")}),
    pandoc.Div({pandoc.Para(img.caption)}, pandoc.Attr("", {"caption"}))
  }, pandoc.Attr("", {"figure"}))
end

return {
  { Meta = meta },
  { Para = figure },
  { Link = link, Image = image, Math = math },
  -- top down, so that code spans already inside a link are left alone
  { traverse = "topdown", Link = function(el) return el, false end,
    Code = code },
}
