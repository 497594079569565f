// placeholder: the browser-script helper writes this file
