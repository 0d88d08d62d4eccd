"""The add-on's entry in Preferences > Add-ons, as Blender builds it: from bl_info read out of
the source with ast.literal_eval (3.4, legacy add-ons) or from the installed
blender_manifest.toml (4.2+ extensions), never from the running module (docs/addon.md,
"Documentation and bug reports")."""
import os
import re
import unittest
import urllib.parse

import addon_utils

import helpers


def preferences_entry():
    """The bl_info Preferences shows for the installed add-on."""
    listed = {mod.__name__: mod for mod in addon_utils.modules(refresh=False)}
    if helpers.MODULE not in listed:
        return None
    return addon_utils.module_bl_info(listed[helpers.MODULE])


class PreferencesEntry(unittest.TestCase):
    def test_listed_with_name_and_description(self):
        """A bl_info that is not one literal (an expression computed at import) is refused by
        Blender's ast.literal_eval: the add-on would vanish from the list while it still runs."""
        info = preferences_entry()
        self.assertIsNotNone(info, f"{helpers.MODULE} in Preferences > Add-ons")
        self.assertEqual(info["name"], "EdgeLight")
        for words in ("highlights", "ink lines", "toon shading"):
            self.assertIn(words, info["description"])

    def test_links_are_web_addresses_or_absent(self):
        """What Preferences would open: bl_info's doc_url and tracker_url (3.4, legacy add-ons)
        and the manifest's website (4.2+ extensions). Blender opens them as written (4.2+ prefix
        one without a scheme with https://), so a path into the install cannot work there, and
        EdgeLight has no public site or tracker: none is set, and any set later is a web address."""
        info = preferences_entry()
        self.assertIsNotNone(info, f"{helpers.MODULE} in Preferences > Add-ons")
        links = {key: info.get(key) or "" for key in ("doc_url", "tracker_url")}
        manifest = os.path.join(os.path.dirname(helpers.addon().__file__), "blender_manifest.toml")
        with open(manifest, encoding="utf-8") as f:
            website = re.search(r'^website\s*=\s*"([^"]*)"', f.read(), re.M)
        links["website"] = website.group(1) if website else ""
        for key, url in links.items():
            if url:
                self.assertIn(urllib.parse.urlparse(url).scheme, ("http", "https"), f"{key} = {url!r}")


if __name__ == "__main__":
    unittest.main()
