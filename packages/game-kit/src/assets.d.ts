/** Stylesheets imported as text (`import css from 'x.css' with { type: 'text' }`), injected at run time. */
declare module '*.css' {
  const text: string;
  export default text;
}
