-- dofile_relative_path_says_folder: a script that runs another scene by a relative path (as the validation
-- wrappers run a shipped scene from the source root), started from a folder where that path is not
dofile("scripts/scenes/baking/no_such_scene.lua")
