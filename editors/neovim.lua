-- chasles in Neovim (0.11 or later): `.chs` files, and `chasles lsp` started
-- for them (LANGUAGE.md §15). Put this in init.lua, or in a file under
-- ~/.config/nvim/plugin/.
vim.filetype.add({ extension = { chs = 'chasles' } })
vim.api.nvim_create_autocmd('FileType', {
  pattern = 'chasles',
  callback = function() vim.bo.commentstring = '# %s' end,
})
vim.lsp.config('chasles', {
  cmd = { 'chasles', 'lsp' },
  filetypes = { 'chasles' },
  root_markers = { '.git' },
})
vim.lsp.enable('chasles')
